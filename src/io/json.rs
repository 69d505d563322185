//! The JSON inputs of the constructions (profile, revolve, sweep), read with serde_json.

use std::path::Path;

use serde::de::DeserializeOwned;

use crate::error::{Error, Result};

/// Deserialize `text`, the contents of `path` (which only names it in messages): a syntax
/// error, an unknown field or a bad value is [`Error::Parse`] with serde_json's line and
/// message.
pub fn parse_json<T: DeserializeOwned>(text: &str, path: &Path) -> Result<T> {
    serde_json::from_str(text).map_err(|e| Error::Parse {
        path: path.to_path_buf(),
        line: e.line(),
        message: e.to_string(),
    })
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn errors_name_the_file_and_line() {
        let e = parse_json::<serde_json::Value>("{\n  \"a\": 1,\n  \"b\": }", Path::new("in.json"));
        match e {
            Err(Error::Parse {
                path,
                line,
                message,
            }) => {
                assert_eq!((path.to_str(), line), (Some("in.json"), 3));
                assert!(message.starts_with("expected value"), "{message}");
            }
            other => panic!("{other:?}"),
        }
        let v: serde_json::Value = parse_json("[1, 2]", Path::new("in.json")).unwrap();
        assert_eq!(v, serde_json::json!([1, 2]));
    }
}
