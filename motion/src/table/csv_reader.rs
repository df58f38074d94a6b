//! Reading cam points from CSV: the Rivet CSV, and the Omron and Delta files Rivet exports
//! (`docs/cam-formats.md` §2.2).

use super::CsvError;
use crate::curve::CamPoint;

/// How many characters of a wrong text an error quotes, so a huge line cannot flood a message.
const QUOTE_CHARS: usize = 40;

/// The headers the reader knows, in lower case: each names the columns in file order, which
/// fill master, slave, velocity and acceleration in that order.
const KNOWN_HEADERS: [&[&str]; 5] = [
    &["master", "slave"],
    &["master", "slave", "velocity"],
    &["master", "slave", "velocity", "acceleration"],
    &["phase", "distance"],
    &["masterpos", "slavepos", "slavevel", "slaveacc"],
];

/// Reads the points of a CSV file: a header naming the columns, then one point per line,
/// master strictly increasing, at least two points. Blank lines and lines starting with `#`
/// are skipped. Columns the header does not name (velocity, acceleration) read as 0.
///
/// Never panics; every error names the 1-based line and the column by its header name.
pub fn read_points_csv(text: &str) -> Result<Vec<CamPoint>, CsvError> {
    let text = text.strip_prefix('\u{feff}').unwrap_or(text);
    let mut lines = text
        .split('\n')
        .enumerate()
        .map(|(index, line)| (index + 1, line.strip_suffix('\r').unwrap_or(line)))
        .filter(|(_, line)| {
            let trimmed = line.trim();
            !trimmed.is_empty() && !trimmed.starts_with('#')
        });
    let (header_line, header_text) = lines.next().ok_or(CsvError::Empty)?;
    let columns: Vec<String> = header_text
        .split(',')
        .map(|field| field.trim().to_owned())
        .collect();
    let lower: Vec<String> = columns.iter().map(|c| c.to_ascii_lowercase()).collect();
    if !KNOWN_HEADERS.iter().any(|known| *known == lower.as_slice()) {
        return Err(CsvError::UnknownHeader {
            line: header_line,
            text: quote(header_text.trim()),
        });
    }

    let mut points: Vec<CamPoint> = Vec::new();
    let mut previous_line = header_line;
    for (line, line_text) in lines {
        let fields: Vec<&str> = line_text.split(',').collect();
        if fields.len() > columns.len() {
            return Err(CsvError::TooManyValues {
                line,
                count: fields.len(),
                columns: columns.len(),
            });
        }
        let mut values = [0.0; 4];
        for (position, column) in columns.iter().enumerate() {
            let field = fields.get(position).map_or("", |f| f.trim());
            values[position] = parse_value(field, line, column)?;
        }
        let point = CamPoint {
            master: values[0],
            slave: values[1],
            velocity: values[2],
            acceleration: values[3],
        };
        if let Some(previous) = points.last()
            && point.master <= previous.master
        {
            return Err(CsvError::MasterNotIncreasing {
                line,
                column: columns[0].clone(),
                master: point.master,
                previous_line,
                previous: previous.master,
            });
        }
        points.push(point);
        previous_line = line;
    }
    if points.len() < 2 {
        return Err(CsvError::TooFewPoints {
            count: points.len(),
        });
    }
    Ok(points)
}

/// One value of a point: a finite decimal number, or an error naming line and column.
fn parse_value(field: &str, line: usize, column: &str) -> Result<f64, CsvError> {
    if field.is_empty() {
        return Err(CsvError::MissingValue {
            line,
            column: column.to_owned(),
        });
    }
    match field.parse::<f64>() {
        // `parse` also takes `inf` and `NaN`, which no cam point may hold.
        Ok(value) if value.is_finite() => Ok(value),
        _ => Err(CsvError::NotANumber {
            line,
            column: column.to_owned(),
            text: quote(field),
        }),
    }
}

/// `text` cut to [`QUOTE_CHARS`] characters, with `…` when it was cut.
fn quote(text: &str) -> String {
    if text.chars().count() > QUOTE_CHARS {
        let mut cut: String = text.chars().take(QUOTE_CHARS).collect();
        cut.push('…');
        cut
    } else {
        text.to_owned()
    }
}
