// Device recordings as CSV: a header naming the columns t,x,y,z,qx,qy,qz,qw (in any order; other
// columns, e.g. a device's button state, are ignored), then one sample per line.
#include "config/recording_formats.hpp"

#include "util/errors.hpp"

#include <charconv>
#include <cmath>
#include <fstream>
#include <map>
#include <sstream>

namespace mssph {
namespace {

std::string trim(const std::string& text) {
  const auto first = text.find_first_not_of(" \t\r");
  if (first == std::string::npos) return "";
  const auto last = text.find_last_not_of(" \t\r");
  return text.substr(first, last - first + 1);
}

std::vector<std::string> split_fields(const std::string& line) {
  std::vector<std::string> fields;
  std::istringstream in(line);
  for (std::string field; std::getline(in, field, ',');) fields.push_back(trim(field));
  if (!line.empty() && line.back() == ',') fields.emplace_back();  // a trailing empty field
  return fields;
}

std::string where(const std::string& path, std::size_t line) { return path + ": line " + std::to_string(line); }

double parse_number(const std::string& field, const std::string& path, std::size_t line, const char* column) {
  double value = 0.0;
  const char* end = field.data() + field.size();
  const auto [stop, error] = std::from_chars(field.data(), end, value);
  if (field.empty() || error != std::errc() || stop != end) {
    throw InputError(where(path, line) + ": column " + column + ": expected a number, got \"" + field + "\"");
  }
  if (!std::isfinite(value)) {
    throw InputError(where(path, line) + ": column " + column + ": expected a finite number, got " + field);
  }
  return value;
}

}  // namespace

RawRecording read_csv_recording(const std::string& path) {
  std::ifstream in(path);
  if (!in) throw InputError(path + ": cannot open the device recording");
  std::string line;
  std::size_t line_number = 0;
  std::vector<std::string> header;
  while (header.empty() && std::getline(in, line)) {
    ++line_number;
    if (!trim(line).empty()) header = split_fields(line);
  }
  const std::size_t header_line = line_number;
  if (header.empty()) throw InputError(path + ": empty file: expected a header t,x,y,z,qx,qy,qz,qw");

  std::map<std::string, std::size_t> index;
  for (std::size_t c = 0; c < header.size(); ++c) {
    if (!index.emplace(header[c], c).second) {
      throw InputError(where(path, header_line) + " (header): column \"" + header[c] + "\" appears twice");
    }
  }
  std::array<std::size_t, 8> column_of{};
  for (std::size_t k = 0; k < kRecordingColumns.size(); ++k) {
    const auto it = index.find(kRecordingColumns[k]);
    if (it == index.end()) {
      throw InputError(where(path, header_line) + " (header): missing column \"" + kRecordingColumns[k] +
                       "\" (expected the columns t,x,y,z,qx,qy,qz,qw)");
    }
    column_of[k] = it->second;
  }

  RawRecording out;
  out.row_word = "line";
  while (std::getline(in, line)) {
    ++line_number;
    if (trim(line).empty()) continue;
    if (out.time.size() == kMaxRecordingSamples) {
      throw InputError(where(path, line_number) + ": more than the " + std::to_string(kMaxRecordingSamples) +
                       " samples a device recording may hold");
    }
    const std::vector<std::string> fields = split_fields(line);
    if (fields.size() != header.size()) {
      throw InputError(where(path, line_number) + ": expected " + std::to_string(header.size()) +
                       " comma-separated values (as in the header), got " + std::to_string(fields.size()));
    }
    std::array<double, 8> values{};
    for (std::size_t k = 0; k < values.size(); ++k) {
      values[k] = parse_number(fields[column_of[k]], path, line_number, kRecordingColumns[k]);
    }
    out.time.push_back(values[0]);
    out.pose.push_back({values[1], values[2], values[3], values[4], values[5], values[6], values[7]});
    out.row_number.push_back(line_number);
  }
  return out;
}

std::string csv_recording_text(const RawRecording& recording) {
  std::ostringstream out;
  for (std::size_t k = 0; k < kRecordingColumns.size(); ++k) out << (k ? "," : "") << kRecordingColumns[k];
  out << "\n";
  // Shortest round-trip decimal form (std::to_chars): a replay reads back the same doubles.
  char buffer[32];
  const auto put = [&](double value) {
    const auto result = std::to_chars(buffer, buffer + sizeof buffer, value);
    out.write(buffer, result.ptr - buffer);
  };
  for (std::size_t i = 0; i < recording.time.size(); ++i) {
    put(recording.time[i]);
    for (double v : recording.pose[i]) {
      out << ',';
      put(v);
    }
    out << '\n';
  }
  return out.str();
}

}  // namespace mssph
