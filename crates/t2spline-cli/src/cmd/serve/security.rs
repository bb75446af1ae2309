//! What every request must show before it is answered: the per-run token,
//! a `Host` of the loopback address and port (a page of another site whose
//! name was made to resolve to 127.0.0.1, DNS rebinding, sends its own host
//! name), and no other site's `Origin` (a cross-origin form or `fetch`).
//!
//! The server binds 127.0.0.1 only, so no other computer reaches it; the
//! token keeps out other users and programs of this computer that cannot
//! read the terminal.

use super::http::Request;

/// Why a request is refused (status 403), as the response says.
#[derive(Debug, PartialEq, Eq)]
pub enum Refusal {
    /// `Host` is missing or names another host or port.
    Host,
    /// `Origin` names another origin than the page's.
    Origin,
    /// The token is missing or wrong.
    Token,
}

impl Refusal {
    /// The message of the response.
    pub fn message(&self) -> &'static str {
        match self {
            Refusal::Host => "refused: the Host header must be 127.0.0.1:PORT or localhost:PORT",
            Refusal::Origin => "refused: a request from another origin",
            Refusal::Token => "refused: the token of this run is missing or wrong (query `token` or header `X-T2spline-Token`)",
        }
    }
}

/// A fresh token: 128 bits from the operating system's random source, in hex.
///
/// # Errors
/// The operating system gives no random bytes.
pub fn new_token() -> anyhow::Result<String> {
    let mut bytes = [0u8; 16];
    getrandom::fill(&mut bytes)
        .map_err(|e| anyhow::anyhow!("no random bytes for the token: {e}"))?;
    Ok(bytes.iter().map(|b| format!("{b:02x}")).collect())
}

/// The value of the query parameter `name` of `url` (no percent-decoding:
/// the token is hex).
pub fn query<'a>(url: &'a str, name: &str) -> Option<&'a str> {
    let (_, query) = url.split_once('?')?;
    query
        .split('&')
        .filter_map(|pair| pair.split_once('='))
        .find(|(k, _)| *k == name)
        .map(|(_, v)| v)
}

/// Equality in a time that does not depend on where the strings differ.
fn same(a: &str, b: &str) -> bool {
    a.len() == b.len()
        && a.bytes()
            .zip(b.bytes())
            .fold(0u8, |acc, (x, y)| acc | (x ^ y))
            == 0
}

/// Checks `request` against the server on `port` with `token`.
///
/// # Errors
/// The first rule it breaks.
pub fn check(request: &Request, port: u16, token: &str) -> Result<(), Refusal> {
    let hosts = [format!("127.0.0.1:{port}"), format!("localhost:{port}")];
    match request.header("Host") {
        Some(h) if hosts.iter().any(|ok| ok == h) => {}
        _ => return Err(Refusal::Host),
    }
    if let Some(origin) = request.header("Origin") {
        if !hosts.iter().any(|h| origin == format!("http://{h}")) {
            return Err(Refusal::Origin);
        }
    }
    if request
        .header("Sec-Fetch-Site")
        .is_some_and(|s| s == "cross-site" || s == "same-site")
    {
        return Err(Refusal::Origin);
    }
    let given = request
        .header("X-T2spline-Token")
        .or_else(|| query(request.url(), "token"));
    match given {
        Some(t) if same(t, token) => Ok(()),
        _ => Err(Refusal::Token),
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn tokens_are_128_random_bits_in_hex() {
        let (a, b) = (new_token().unwrap(), new_token().unwrap());
        assert_eq!(a.len(), 32);
        assert!(a.bytes().all(|c| c.is_ascii_hexdigit()));
        assert_ne!(a, b);
    }

    #[test]
    fn the_query_gives_its_parameter() {
        assert_eq!(query("/?token=ab12&x=1", "token"), Some("ab12"));
        assert_eq!(query("/api/run?x=1&token=cd", "token"), Some("cd"));
        assert_eq!(query("/api/run", "token"), None);
        assert_eq!(query("/?tokenx=1", "token"), None);
    }

    #[test]
    fn equality_is_exact() {
        assert!(same("abc", "abc"));
        assert!(!same("abc", "abd"));
        assert!(!same("abc", "abcd"));
        assert!(!same("", "a"));
    }
}
