//! t2spline-io
