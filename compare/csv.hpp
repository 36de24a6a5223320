#pragma once
// CSV as the report writes and reads it (results.csv, failure_map.csv).
//
// Statement. RFC 4180: fields are separated by commas and records end with a
// line break; a field that holds a comma, a double quote, a line break or a
// leading or trailing space is written between double quotes, each double
// quote inside it doubled. Every other field is written as it is. The reader
// takes the same dialect (quoted and unquoted fields, doubled quotes, line
// breaks inside quotes, CRLF or LF line ends) and is the inverse of the
// writer: csv_records(csv_line(f) + "\n") == {f} for every list f of strings.
// Python's `csv` module (compare/plots/report_figures.py) reads the same files.
// Errors name the file (`where`) and the line: an unterminated quote, or text
// after a closing quote.
// Requirements: none (strings only).
#include <string>
#include <string_view>
#include <vector>

namespace eccd {

// One field, quoted if it needs to be.
std::string csv_field(std::string_view text);
// One record without its line break: the fields quoted as needed, joined by commas.
std::string csv_line(const std::vector<std::string>& fields);

// One parsed record and the line (1-based) it starts on.
struct CsvRecord {
  std::vector<std::string> fields;
  int line = 0;
};
// Every record of `text` (a last record without a line break counts; an empty
// text has none). Throws std::invalid_argument("WHERE: line N: ...") on
// malformed quoting.
std::vector<CsvRecord> csv_records(const std::string& text, const std::string& where);
// The fields of one record given without its line break (a line as
// csv_line writes it).
std::vector<std::string> csv_split(const std::string& line, const std::string& where = "CSV record");

}  // namespace eccd
