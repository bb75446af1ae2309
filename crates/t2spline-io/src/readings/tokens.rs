//! Fields of delimited text with their places: comma- or semicolon-separated
//! values as spreadsheets write them (RFC 4180 quoting, CRLF or LF line ends).
//!
//! The `csv` crate, which writes the result tables, reports a record's line
//! but not where each field starts; messages about readings name the line
//! and the character column of the field, so the few rules of the format are
//! followed here, with positions.

/// One field: its text (quotes removed, `""` turned into `"`) and where it
/// starts (line and character column, from 1).
#[derive(Clone, Debug, PartialEq, Eq)]
pub(crate) struct Field {
    pub text: String,
    pub line: usize,
    pub column: usize,
}

/// One record (a row): its fields, and where its line ends (for a missing
/// field, the place after the last one).
#[derive(Clone, Debug, PartialEq, Eq)]
pub(crate) struct Record {
    pub fields: Vec<Field>,
    pub end: (usize, usize),
}

/// A fault of the quoting, at a line and column.
#[derive(Clone, Debug, PartialEq, Eq)]
pub(crate) struct QuoteError {
    pub line: usize,
    pub column: usize,
    pub message: &'static str,
}

/// Why the text could not be split into records.
#[derive(Clone, Debug, PartialEq, Eq)]
pub(crate) enum Fault {
    /// A fault of the quoting.
    Quote(QuoteError),
    /// More than the most records allowed (blank lines are not records); the
    /// records past the limit are neither stored nor counted.
    TooMany,
}

/// Splits `text` into records of fields separated by `delimiter`; blank lines
/// are skipped. A record ends at `\n`, `\r\n` or a lone `\r` outside quotes.
/// More than `max` records (the header among them) is [`Fault::TooMany`],
/// found before a record past the limit is stored.
pub(crate) fn records(text: &str, delimiter: char, max: usize) -> Result<Vec<Record>, Fault> {
    let mut out = Vec::new();
    each_record(text, delimiter, max, |record| out.push(record))?;
    Ok(out)
}

/// As [`records`], but hands each record to `take` as it is read, so that a
/// reader keeps only what it makes of them; gives the count of records.
/// More than `max` is [`Fault::TooMany`], found before the record past the
/// limit is handed over.
pub(crate) fn each_record(
    text: &str,
    delimiter: char,
    max: usize,
    mut take: impl FnMut(Record),
) -> Result<usize, Fault> {
    let mut count = 0usize;
    let mut chars = text.chars().peekable();
    let (mut line, mut column) = (1, 1);
    let mut fields: Vec<Field> = Vec::new();
    let mut field = Field {
        text: String::new(),
        line,
        column,
    };
    let mut after_quote = false;
    let mut quoted_start: Option<(usize, usize)> = None;
    loop {
        let c = chars.next();
        if let Some((qline, qcolumn)) = quoted_start {
            match c {
                None => {
                    return Err(Fault::Quote(QuoteError {
                        line: qline,
                        column: qcolumn,
                        message: "a quoted field is not closed",
                    }))
                }
                Some('"') if chars.peek() == Some(&'"') => {
                    chars.next();
                    field.text.push('"');
                    column += 2;
                }
                Some('"') => {
                    quoted_start = None;
                    after_quote = true;
                    column += 1;
                }
                Some('\n') => {
                    field.text.push('\n');
                    line += 1;
                    column = 1;
                }
                Some(ch) => {
                    field.text.push(ch);
                    column += 1;
                }
            }
            continue;
        }
        let end_of_line = match c {
            None | Some('\n') => true,
            Some('\r') => {
                if chars.peek() == Some(&'\n') {
                    chars.next();
                }
                true
            }
            _ => false,
        };
        if end_of_line || c == Some(delimiter) {
            let next = Field {
                text: String::new(),
                line,
                column: column + 1,
            };
            fields.push(std::mem::replace(&mut field, next));
            after_quote = false;
            if end_of_line {
                let end = (line, column);
                let blank = matches!(&fields[..], [only] if only.text.trim().is_empty());
                if !blank {
                    if count == max {
                        return Err(Fault::TooMany);
                    }
                    count += 1;
                    take(Record {
                        fields: std::mem::take(&mut fields),
                        end,
                    });
                }
                fields.clear();
                if c.is_none() {
                    return Ok(count);
                }
                line += 1;
                column = 1;
                field = Field {
                    text: String::new(),
                    line,
                    column,
                };
                continue;
            }
            column += 1;
            continue;
        }
        // `c` is neither the end nor a delimiter here.
        let ch = c.unwrap_or_default();
        if after_quote && !ch.is_whitespace() {
            return Err(Fault::Quote(QuoteError {
                line,
                column,
                message: "text after the closing quote of a field; a quote inside a quoted field is written twice (\"\")",
            }));
        }
        if ch == '"' && field.text.trim().is_empty() && !after_quote {
            field.text.clear();
            quoted_start = Some((line, column));
        } else if !after_quote {
            field.text.push(ch);
        }
        column += 1;
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    fn records(text: &str, delimiter: char) -> Result<Vec<Record>, QuoteError> {
        super::records(text, delimiter, usize::MAX).map_err(|e| match e {
            Fault::Quote(q) => q,
            Fault::TooMany => panic!("no limit"),
        })
    }

    fn texts(r: &[Record]) -> Vec<Vec<&str>> {
        r.iter()
            .map(|r| r.fields.iter().map(|f| f.text.as_str()).collect())
            .collect()
    }

    #[test]
    fn fields_lines_and_columns() {
        let r = records("station,x,y\r\nA,1.5,2\n\nB,3,4", ',').unwrap();
        assert_eq!(
            texts(&r),
            [
                vec!["station", "x", "y"],
                vec!["A", "1.5", "2"],
                vec!["B", "3", "4"]
            ]
        );
        let b = &r[2].fields;
        assert_eq!((b[0].line, b[0].column), (4, 1));
        assert_eq!((b[2].line, b[2].column), (4, 5));
        assert_eq!(r[1].end, (2, 8));
    }

    #[test]
    fn quotes_as_spreadsheets_write_them() {
        let r = records("\"st;1\";\"1,5\";\"a \"\"b\"\"\"\n", ';').unwrap();
        assert_eq!(texts(&r), [vec!["st;1", "1,5", "a \"b\""]]);
        let e = records("\"A\"x,1,2", ',').unwrap_err();
        assert_eq!((e.line, e.column), (1, 4));
        let e = records("A,\"1,2\n", ',').unwrap_err();
        assert_eq!(
            (e.line, e.column, e.message),
            (1, 3, "a quoted field is not closed")
        );
    }

    #[test]
    fn the_limit_counts_records_not_lines() {
        // Three records among blank lines, CRLF, lone CR and a quoted line end.
        let text = "h,x\n\n  \r\na,\"1\n2\"\r\n\rb,3\n\n";
        assert_eq!(super::records(text, ',', 3).map(|r| r.len()), Ok(3));
        assert_eq!(super::records(text, ',', 2), Err(Fault::TooMany));
        // A lone CR ends a record for the limit too.
        assert_eq!(super::records("h\ra\rb\r", ',', 2), Err(Fault::TooMany));
    }

    #[test]
    fn a_lone_carriage_return_ends_a_line() {
        let r = records("a,b\rc,d\r", ',').unwrap();
        assert_eq!(texts(&r), [vec!["a", "b"], vec!["c", "d"]]);
        assert_eq!(r[1].fields[1].line, 2);
    }
}
