//! Bad input: each error names the line, column and element path.

use crate::{MAX_FILE_BYTES, ReadError, ReadErrorKind, ReadFileError, read, read_bytes, read_file};

/// A v2.01 document whose program `Main` has an FBD body of `objects`, which start on line 7.
fn with_fbd(objects: &str) -> String {
    format!(
        r#"<?xml version="1.0" encoding="UTF-8"?>
<project xmlns="http://www.plcopen.org/xml/tc6_0201">
  <fileHeader companyName="c" productName="p" productVersion="1" creationDateTime="2024-01-01T00:00:00"/>
  <contentHeader name="n"><coordinateInfo><fbd><scaling x="0" y="0"/></fbd><ld><scaling x="0" y="0"/></ld><sfc><scaling x="0" y="0"/></sfc></coordinateInfo></contentHeader>
  <types><dataTypes/><pous>
    <pou name="Main" pouType="program"><body><FBD>
{objects}
    </FBD></body></pou>
  </pous></types>
</project>
"#
    )
}

fn read_error(text: &str) -> ReadError {
    match read(text, "bad.xml") {
        Ok(document) => panic!("read: {document:?}"),
        Err(error) => error,
    }
}

const IN_VARIABLE_7: &str = r#"      <inVariable localId="7"><position x="0" y="0"/><connectionPointOut/><expression>a</expression></inVariable>"#;

#[test]
fn a_valid_body_reads() {
    let document =
        read(&with_fbd(IN_VARIABLE_7), "good.xml").unwrap_or_else(|error| panic!("{error}"));
    assert_eq!(document.pous[0].bodies[0].content.objects()[0].local_id, 7);
}

#[test]
fn a_truncated_file_is_not_xml() {
    let text = with_fbd(IN_VARIABLE_7);
    let cut = &text[..text.find("</FBD>").unwrap_or(text.len())];
    let error = read_error(cut);
    assert!(matches!(error.kind, ReadErrorKind::NotXml(_)), "{error}");
    // The text ends after the four spaces of line 8.
    assert_eq!((error.line, error.column), (8, 5), "{error}");
    assert!(
        error
            .to_string()
            .starts_with("bad.xml:8:5: not well-formed XML: "),
        "{error}"
    );
}

#[test]
fn text_that_is_not_xml_is_refused() {
    let error = read_error("PROGRAM Main\nEND_PROGRAM\n");
    assert!(matches!(error.kind, ReadErrorKind::NotXml(_)), "{error}");
    assert_eq!((error.line, error.column), (1, 1));
}

#[test]
fn a_root_that_is_not_a_project_is_refused() {
    let error = read_error(
        "<?xml version=\"1.0\"?>\n  <plcProject xmlns=\"http://www.plcopen.org/xml/tc6_0201\"/>",
    );
    assert_eq!(
        error.kind,
        ReadErrorKind::WrongRoot {
            found: "plcProject".to_owned()
        }
    );
    assert_eq!((error.line, error.column), (2, 3));
}

#[test]
fn an_unknown_namespace_is_refused() {
    let text = with_fbd(IN_VARIABLE_7).replace("tc6_0201", "tc6_0300");
    let error = read_error(&text);
    assert_eq!(
        error.kind,
        ReadErrorKind::WrongNamespace {
            found: "http://www.plcopen.org/xml/tc6_0300".to_owned()
        }
    );
    assert_eq!(
        (error.line, error.column, error.path.as_str()),
        (2, 1, "project")
    );
}

#[test]
fn a_missing_required_attribute_names_line_column_and_path() {
    let error = read_error(&with_fbd(
        r#"      <block localId="7"><position x="0" y="0"/><inputVariables/><inOutVariables/><outputVariables/></block>"#,
    ));
    assert_eq!(
        error.kind,
        ReadErrorKind::MissingAttribute {
            attribute: "typeName"
        }
    );
    assert_eq!((error.line, error.column), (7, 7));
    assert_eq!(
        error.to_string(),
        "bad.xml:7:7: project/types/pous/pou[@name='Main']/body/FBD/block[@localId='7']: \
         the required attribute `typeName` is missing"
    );
}

#[test]
fn a_local_id_that_is_not_a_number_is_refused_at_the_attribute() {
    let error = read_error(&with_fbd(&IN_VARIABLE_7.replace("\"7\"", "\"seven\"")));
    assert_eq!(
        error.kind,
        ReadErrorKind::BadAttribute {
            attribute: "localId",
            value: "seven".to_owned(),
            expected: "an unsigned integer"
        }
    );
    assert_eq!((error.line, error.column), (7, 19));
    assert_eq!(
        error.path,
        "project/types/pous/pou[@name='Main']/body/FBD/inVariable[@localId='seven']"
    );
}

#[test]
fn a_connection_to_no_element_is_refused() {
    let objects = format!(
        "{IN_VARIABLE_7}\n      <outVariable localId=\"8\"><connectionPointIn><connection refLocalId=\"9\"/></connectionPointIn><expression>b</expression></outVariable>"
    );
    let error = read_error(&with_fbd(&objects));
    assert_eq!(
        error.kind,
        ReadErrorKind::DanglingReference { ref_local_id: 9 }
    );
    assert_eq!((error.line, error.column), (8, 63));
    assert_eq!(
        error.path,
        "project/types/pous/pou[@name='Main']/body/FBD/outVariable[@localId='8']/connectionPointIn/connection"
    );
}

#[test]
fn duplicate_local_ids_in_a_body_are_refused() {
    let error = read_error(&with_fbd(&format!("{IN_VARIABLE_7}\n{IN_VARIABLE_7}")));
    assert_eq!(
        error.kind,
        ReadErrorKind::DuplicateLocalId {
            local_id: 7,
            first_line: 7
        }
    );
    assert_eq!((error.line, error.column), (8, 19));
}

#[test]
fn an_unknown_element_in_a_body_is_refused() {
    let error = read_error(&with_fbd("      <gadget localId=\"1\"/>"));
    assert!(
        matches!(&error.kind, ReadErrorKind::UnexpectedElement { element, .. } if element == "gadget")
    );
    assert_eq!((error.line, error.column), (7, 7));
}

#[test]
fn duplicate_pou_names_are_refused_ignoring_case() {
    let text = with_fbd(IN_VARIABLE_7).replace(
        "  </pous></types>",
        "    <pou name=\"MAIN\" pouType=\"function\"><body><ST/></body></pou>\n  </pous></types>",
    );
    let error = read_error(&text);
    assert_eq!(
        error.kind,
        ReadErrorKind::DuplicateName {
            what: "POU",
            name: "MAIN".to_owned(),
            first_what: "POU",
            first_line: 6
        }
    );
    assert_eq!((error.line, error.column), (9, 10));
}

#[test]
fn bytes_that_are_not_utf8_are_refused_where_they_start() {
    let mut bytes = with_fbd(IN_VARIABLE_7).into_bytes();
    // Line 2 starts after the declaration; put a Latin-1 byte in the middle of `xmlns`.
    let line_2 = bytes.iter().position(|byte| *byte == b'\n').unwrap_or(0) + 1;
    bytes[line_2 + 3] = 0xE9;
    let error = match read_bytes(&bytes, "latin1.xml") {
        Ok(_) => panic!("read"),
        Err(error) => error,
    };
    assert_eq!(error.kind, ReadErrorKind::NotUtf8);
    assert_eq!((error.line, error.column), (2, 4));
}

#[test]
fn utf16_and_a_utf8_byte_order_mark_are_read() {
    let text = with_fbd(IN_VARIABLE_7);
    let mut utf16 = vec![0xFF, 0xFE];
    utf16.extend(text.encode_utf16().flat_map(u16::to_le_bytes));
    let document = read_bytes(&utf16, "utf16.xml").unwrap_or_else(|error| panic!("{error}"));
    assert_eq!(document.pous[0].name, "Main");
    let big_endian: Vec<u8> = text.encode_utf16().flat_map(u16::to_be_bytes).collect();
    let document = read_bytes(&big_endian, "utf16be.xml").unwrap_or_else(|error| panic!("{error}"));
    assert_eq!(document.pous[0].name, "Main");
    let mut with_bom = vec![0xEF, 0xBB, 0xBF];
    with_bom.extend(text.as_bytes());
    assert!(read_bytes(&with_bom, "bom.xml").is_ok());
}

#[test]
fn utf16_with_an_unpaired_surrogate_is_refused_where_it_stands() {
    let mut utf16 = vec![0xFF, 0xFE];
    utf16.extend("<project>\n  ".encode_utf16().flat_map(u16::to_le_bytes));
    utf16.extend(0xDC00u16.to_le_bytes());
    let error = match read_bytes(&utf16, "utf16.xml") {
        Ok(_) => panic!("read"),
        Err(error) => error,
    };
    assert_eq!(error.kind, ReadErrorKind::NotUtf16);
    assert_eq!((error.line, error.column), (2, 3));
}

#[test]
fn a_file_over_the_limit_is_refused_before_parsing() {
    let bytes = vec![b' '; MAX_FILE_BYTES + 1];
    let error = match read_bytes(&bytes, "huge.xml") {
        Ok(_) => panic!("read"),
        Err(error) => error,
    };
    assert_eq!(
        error.kind,
        ReadErrorKind::TooLarge {
            size_bytes: Some(MAX_FILE_BYTES + 1),
            limit_bytes: MAX_FILE_BYTES
        }
    );
    assert_eq!((error.line, error.column), (1, 1));
    assert_eq!(
        error.to_string(),
        "huge.xml:1:1: the file has 33554433 bytes (32.0 MiB), more than the 32 MiB a PLCopen XML \
         file may have"
    );
}

#[test]
fn a_50_mb_file_is_refused_from_its_size_without_being_read() {
    // A sparse file: 50 MB long, nothing written, so the test neither writes nor reads 50 MB.
    let path = std::env::temp_dir().join(format!("plcopen-50mb-{}.xml", std::process::id()));
    let file = std::fs::File::create(&path).unwrap_or_else(|error| panic!("{error}"));
    file.set_len(50_000_000)
        .unwrap_or_else(|error| panic!("{error}"));
    let outcome = read_file(&path);
    std::fs::remove_file(&path).unwrap_or_else(|error| panic!("{error}"));
    let Err(ReadFileError::Read(error)) = outcome else {
        panic!("{outcome:?}")
    };
    assert_eq!(
        error.kind,
        ReadErrorKind::TooLarge {
            size_bytes: Some(50_000_000),
            limit_bytes: MAX_FILE_BYTES
        }
    );
    assert_eq!(
        error.to_string(),
        format!(
            "{}:1:1: the file has 50000000 bytes (47.7 MiB), more than the 32 MiB a PLCopen XML \
             file may have",
            path.display()
        )
    );
}

#[cfg(target_os = "linux")]
#[test]
fn a_file_without_a_size_is_read_no_further_than_the_limit() {
    // `/dev/zero` has no size in its metadata and never ends.
    let outcome = read_file(std::path::Path::new("/dev/zero"));
    let Err(ReadFileError::Read(error)) = outcome else {
        panic!("{outcome:?}")
    };
    assert_eq!(
        error.to_string(),
        "/dev/zero:1:1: the file has more than the 32 MiB a PLCopen XML file may have"
    );
}

#[test]
fn a_missing_header_element_is_named() {
    let text = with_fbd(IN_VARIABLE_7).replace(
        "<coordinateInfo><fbd><scaling x=\"0\" y=\"0\"/></fbd>",
        "<coordinateInfo>",
    );
    let error = read_error(&text);
    assert_eq!(error.kind, ReadErrorKind::MissingElement { element: "fbd" });
    assert_eq!(
        (error.line, error.column, error.path.as_str()),
        (4, 27, "project/contentHeader[@name='n']/coordinateInfo")
    );
}

#[test]
fn an_unknown_child_of_a_body_object_is_refused() {
    let error = read_error(&with_fbd(
        &IN_VARIABLE_7.replace("<expression>", "<negation/><expression>"),
    ));
    assert!(
        matches!(&error.kind, ReadErrorKind::UnexpectedElement { element, .. } if element == "negation"),
        "{error}"
    );
    assert_eq!((error.line, error.column), (7, 75));
    assert_eq!(
        error.path,
        "project/types/pous/pou[@name='Main']/body/FBD/inVariable[@localId='7']/negation"
    );
}

#[test]
fn a_missing_file_is_named() {
    let path = std::path::Path::new(concat!(env!("CARGO_MANIFEST_DIR"), "/no-such-file.xml"));
    let error = match read_file(path) {
        Ok(_) => panic!("read"),
        Err(error) => error,
    };
    assert!(matches!(&error, ReadFileError::Io { file, .. } if file.ends_with("no-such-file.xml")));
    assert!(error.to_string().contains("no-such-file.xml: "), "{error}");
}

#[test]
fn a_pin_is_named_by_its_formal_parameter_in_the_path() {
    let error = read_error(&with_fbd(
        r#"      <block localId="3" typeName="ADD"><inputVariables><variable formalParameter="IN1" negated="maybe"/></inputVariables><inOutVariables/><outputVariables/></block>"#,
    ));
    assert_eq!(
        error.path,
        "project/types/pous/pou[@name='Main']/body/FBD/block[@localId='3']/inputVariables/variable[@formalParameter='IN1']"
    );
    assert_eq!((error.line, error.column), (7, 89));
}

#[test]
fn types_nested_deeper_than_the_limit_are_refused_without_overflowing_the_stack() {
    // An array of an array of … 400,000 deep: 68 bytes a level, under the size and node
    // limits, which the reader's recursion over types would follow off its stack.
    let levels = 400_000;
    let level = "<array><dimension lower=\"0\" upper=\"1\"/><baseType>";
    let start = "<types><dataTypes><dataType name=\"T\"><baseType>";
    let header = r#"<project xmlns="http://www.plcopen.org/xml/tc6_0201">
<fileHeader companyName="c" productName="p" productVersion="1" creationDateTime="2024-01-01T00:00:00"/>
<contentHeader name="n"><coordinateInfo><fbd><scaling x="0" y="0"/></fbd><ld><scaling x="0" y="0"/></ld><sfc><scaling x="0" y="0"/></sfc></coordinateInfo></contentHeader>
"#;
    let mut text = format!("{header}{start}");
    text.push_str(&level.repeat(levels));
    text.push_str("<BOOL/>");
    text.push_str(&"</baseType></array>".repeat(levels));
    text.push_str("</baseType></dataType></dataTypes></types></project>\n");
    let error = read_error(&text);
    assert!(
        matches!(
            error.kind,
            ReadErrorKind::TooDeep {
                limit: crate::MAX_DEPTH
            }
        ),
        "{error}"
    );
    // project, types, dataTypes, dataType and baseType are five levels; each array two more
    // (its dimension and baseType one below it): the first element past 128 is the 62nd
    // array's dimension.
    let column = start.len() + 61 * level.len() + "<array>".len() + 1;
    assert_eq!((error.line, error.column), (4, column as u32), "{error}");
}
