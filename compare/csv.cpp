// CSV with RFC 4180 quoting (see compare/csv.hpp).
#include "compare/csv.hpp"

#include <stdexcept>

namespace eccd {

std::string csv_field(std::string_view t) {
  bool quote = t.find_first_of(",\"\r\n") != std::string_view::npos ||
               (!t.empty() && (t.front() == ' ' || t.back() == ' ' || t.front() == '\t' || t.back() == '\t'));
  if (!quote) return std::string(t);
  std::string q = "\"";
  for (char c : t) {
    if (c == '"') q += '"';
    q += c;
  }
  return q + "\"";
}

std::string csv_line(const std::vector<std::string>& fields) {
  std::string out;
  for (std::size_t k = 0; k < fields.size(); ++k) {
    if (k) out += ',';
    out += csv_field(fields[k]);
  }
  return out;
}

std::vector<CsvRecord> csv_records(const std::string& text, const std::string& where) {
  std::vector<CsvRecord> out;
  std::size_t i = 0, n = text.size();
  int line = 1;
  auto fail = [&](int at, const std::string& what) {
    throw std::invalid_argument(where + ": line " + std::to_string(at) + ": " + what);
  };
  while (i < n) {
    CsvRecord rec;
    rec.line = line;
    std::string field;
    bool end_of_record = false;
    while (!end_of_record) {
      field.clear();
      if (i < n && text[i] == '"') {  // quoted field
        int start = line;
        ++i;
        while (true) {
          if (i >= n) fail(start, "a quoted field is not closed (truncated?)");
          char c = text[i++];
          if (c == '"') {
            if (i < n && text[i] == '"') {
              field += '"';
              ++i;
              continue;
            }
            break;
          }
          if (c == '\n') ++line;
          field += c;
        }
        if (i < n && text[i] != ',' && text[i] != '\n' && text[i] != '\r')
          fail(line, "text after the closing quote of a field (a quote inside a field must be doubled)");
      } else {
        while (i < n && text[i] != ',' && text[i] != '\n' && text[i] != '\r') {
          if (text[i] == '"')
            fail(line, "a quote inside an unquoted field (the field must be quoted, its quotes doubled)");
          field += text[i++];
        }
      }
      rec.fields.push_back(field);
      if (i >= n) {
        end_of_record = true;
      } else if (text[i] == ',') {
        ++i;
      } else {  // line break: \n, \r\n or a lone \r
        if (text[i] == '\r') ++i;
        if (i < n && text[i] == '\n') ++i;
        ++line;
        end_of_record = true;
      }
    }
    out.push_back(std::move(rec));
  }
  return out;
}

std::vector<std::string> csv_split(const std::string& line, const std::string& where) {
  auto r = csv_records(line, where);
  if (r.empty()) return {""};
  if (r.size() != 1) throw std::invalid_argument(where + ": one record expected, found " + std::to_string(r.size()));
  return r[0].fields;
}

}  // namespace eccd
