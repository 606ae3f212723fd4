// The one CSV reader of the program's files (profiles, a wear run's summary and snapshots for the plots):
// "# key: value" comment lines, a header row, data rows; blank lines skipped, cells trimmed, RFC 4180
// quoting (lib/io/csv.h csv_text) undone, a UTF-8 byte order mark dropped. It checks nothing about the
// columns: each caller checks the header and the rows it needs and words its own errors, with the line
// numbers (from 1) the table keeps.
#pragma once

#include <cerrno>
#include <cstring>
#include <fstream>
#include <map>
#include <stdexcept>
#include <string>
#include <utility>
#include <vector>

namespace contact {

struct CsvTable {
  std::string path;
  std::map<std::string, std::pair<std::string, int>> comments;  // "# key: value" -> (value, line)
  std::vector<std::string> header;                              // empty: no row at all
  int header_line = 0;
  std::string header_text;                                      // the header row as written (trimmed)
  std::vector<std::vector<std::string>> rows;
  std::vector<int> row_lines;
  std::vector<std::string> row_texts;                           // each row as written (trimmed)
};

inline std::string csv_trim(const std::string& s) {
  const std::size_t first = s.find_first_not_of(" \t\r");
  if (first == std::string::npos) return "";
  return s.substr(first, s.find_last_not_of(" \t\r") + 1 - first);
}

// one CSV line's cells, trimmed, quoting undone ("a,b," has three cells, the last empty)
inline std::vector<std::string> split_csv_line(const std::string& line) {
  std::vector<std::string> cells(1);
  bool quoted = false;
  for (std::size_t k = 0; k < line.size(); ++k) {
    const char ch = line[k];
    if (quoted) {
      if (ch == '"' && k + 1 < line.size() && line[k + 1] == '"') {
        cells.back() += '"';
        ++k;
      } else if (ch == '"') {
        quoted = false;
      } else {
        cells.back() += ch;
      }
    } else if (ch == '"') {
      quoted = true;
    } else if (ch == ',') {
      cells.emplace_back();
    } else {
      cells.back() += ch;
    }
  }
  for (std::string& c : cells) c = csv_trim(c);
  return cells;
}

// the file's comments, header and rows; throws std::runtime_error "cannot read PATH: reason" when the file
// cannot be read (callers that take it as bad input catch it)
inline CsvTable read_csv_table(const std::string& path) {
  std::ifstream in(path, std::ios::binary);
  if (!in) throw std::runtime_error("cannot read " + path + ": " + std::strerror(errno));
  CsvTable t;
  t.path = path;
  std::string line;
  for (int number = 1; std::getline(in, line); ++number) {
    if (number == 1 && line.rfind("\xEF\xBB\xBF", 0) == 0) line.erase(0, 3);  // a UTF-8 byte order mark
    std::string text = csv_trim(line);
    if (text.empty()) continue;
    if (text[0] == '#') {
      const std::string comment = csv_trim(text.substr(1));
      const std::size_t colon = comment.find(':');
      if (colon != std::string::npos)
        t.comments.emplace(csv_trim(comment.substr(0, colon)), std::make_pair(csv_trim(comment.substr(colon + 1)), number));
      continue;
    }
    std::vector<std::string> cells = split_csv_line(text);
    if (t.header.empty()) {
      t.header = std::move(cells);
      t.header_line = number;
      t.header_text = std::move(text);
      continue;
    }
    t.rows.push_back(std::move(cells));
    t.row_lines.push_back(number);
    t.row_texts.push_back(std::move(text));
  }
  if (in.bad()) throw std::runtime_error("cannot read " + path + ": " + std::strerror(errno));
  return t;
}

}  // namespace contact
