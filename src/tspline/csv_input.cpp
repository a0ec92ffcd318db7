// CSV with a header -> the .xyz text the library's reader checks.

#include "csv_input.h"

#include <CGAL/Triangular_spline/exceptions.h>

#include <algorithm>
#include <cctype>
#include <cstddef>
#include <string>
#include <vector>

namespace tspline {

namespace {

std::string trimmed(const std::string& s) {
  std::size_t b = 0, e = s.size();
  while (b < e && std::isspace(static_cast<unsigned char>(s[b])))
    ++b;
  while (e > b && std::isspace(static_cast<unsigned char>(s[e - 1])))
    --e;
  std::string t = s.substr(b, e - b);
  // spreadsheets quote header names
  if (t.size() >= 2 && t.front() == '"' && t.back() == '"')
    t = t.substr(1, t.size() - 2);
  return t;
}

std::vector<std::string> fields(const std::string& line) {
  std::vector<std::string> result;
  std::size_t start = 0;
  for (;;) {
    const std::size_t comma = line.find(',', start);
    result.push_back(trimmed(line.substr(start, comma - start)));
    if (comma == std::string::npos)
      return result;
    start = comma + 1;
  }
}

std::string lower(std::string s) {
  std::transform(s.begin(), s.end(), s.begin(),
                 [](unsigned char c) { return static_cast<char>(std::tolower(c)); });
  return s;
}

bool blank(const std::string& line) {
  return std::all_of(line.begin(), line.end(),
                     [](unsigned char c) { return std::isspace(c) != 0; });
}

} // namespace

std::string csv_as_xyz(std::istream& in, const std::string& source, const std::string& columns,
                       bool gradients) {
  namespace TS = CGAL::Triangular_spline;
  const std::vector<std::string> roles = gradients
                                             ? std::vector<std::string>{"x", "y", "z", "zx", "zy"}
                                             : std::vector<std::string>{"x", "y", "z"};
  std::vector<std::string> wanted = columns.empty() ? roles : fields(columns);
  if (wanted.size() != roles.size())
    throw TS::Invalid_input("--columns expects " + std::to_string(roles.size()) + " names (" +
                            (gradients ? "x,y,z,zx,zy" : "x,y,z") + "), got '" + columns + "'");
  std::string line, text;
  std::size_t number = 0;
  // the header: the first line that is not blank or a '#' comment
  std::vector<std::string> header;
  while (header.empty() && std::getline(in, line)) {
    ++number;
    text += "#\n";
    if (!blank(line) && trimmed(line).front() != '#')
      header = fields(line);
  }
  if (header.empty())
    throw TS::Invalid_input(source +
                            ": empty CSV file (expected a header line naming the columns)");
  std::vector<std::size_t> index;
  for (const std::string& name : wanted) {
    std::size_t found = header.size();
    for (std::size_t c = 0; c < header.size(); ++c)
      if (header[c] == name || (columns.empty() && lower(header[c]) == name))
        found = c;
    if (found == header.size()) {
      std::string names;
      for (const std::string& h : header)
        names += (names.empty() ? "'" : ", '") + h + "'";
      throw TS::Invalid_input(source + ":" + std::to_string(number) + ": no column named '" + name +
                              "' in the header (" + names + ")" +
                              (columns.empty() ? "; choose them with --columns X,Y,Z" : ""));
    }
    index.push_back(found);
  }
  while (std::getline(in, line)) {
    ++number;
    if (!line.empty() && line.back() == '\r')
      line.pop_back();
    if (blank(line)) {
      text += "\n";
      continue;
    }
    const std::vector<std::string> row = fields(line);
    const std::string where = source + ":" + std::to_string(number) + ": ";
    if (row.size() != header.size())
      throw TS::Invalid_input(where + "expected " + std::to_string(header.size()) +
                              " comma-separated fields as in the header, found " +
                              std::to_string(row.size()));
    for (std::size_t k = 0; k < index.size(); ++k) {
      const std::string& field = row[index[k]];
      // one token per field: the .xyz reader splits at blanks and reads '#' as a comment
      if (field.empty() || field.find_first_of(" \t#") != std::string::npos)
        throw TS::Invalid_input(where + "column '" + header[index[k]] + "': '" + field +
                                "' is not a number");
      text += field;
      text += k + 1 < index.size() ? ' ' : '\n';
    }
  }
  if (in.bad())
    throw TS::Invalid_input(source + ": read error");
  return text;
}

std::vector<std::size_t> npy_column_indices(const std::string& columns, std::size_t rows,
                                            std::size_t array_columns, bool gradients,
                                            const std::string& source) {
  namespace TS = CGAL::Triangular_spline;
  const std::size_t wanted = gradients ? 5 : 3;
  const std::string names = gradients ? "x, y, z, zx, zy" : "x, y, z";
  std::vector<std::size_t> index;
  if (columns.empty()) {
    if (array_columns != wanted)
      throw TS::Invalid_input(source + ": an array of shape (" + std::to_string(rows) + ", " +
                              std::to_string(array_columns) + "): choose the columns of " + names +
                              " with --columns (indices from 0, e.g. --columns " +
                              (gradients ? "0,1,2,3,4" : "0,1,2") + ")");
    for (std::size_t c = 0; c < wanted; ++c)
      index.push_back(c);
    return index;
  }
  for (const std::string& field : fields(columns)) {
    // digits only: stoul would take "-1", " 2" or "1x"
    if (field.empty() || field.size() > 9 ||
        !std::all_of(field.begin(), field.end(), [](unsigned char c) { return std::isdigit(c); }))
      throw TS::Invalid_input("--columns of a .npy input are column indices from 0 (e.g. 0,1,2), "
                              "not '" +
                              columns + "'");
    index.push_back(static_cast<std::size_t>(std::stoul(field)));
  }
  if (index.size() != wanted)
    throw TS::Invalid_input("--columns expects " + std::to_string(wanted) + " indices (" + names +
                            "), got '" + columns + "'");
  return index;
}

} // namespace tspline
