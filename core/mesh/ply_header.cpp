// SPDX-License-Identifier: MIT
#include "mesh/ply_header.h"

#include <array>
#include <charconv>
#include <cstdint>
#include <fstream>
#include <sstream>
#include <string>
#include <string_view>
#include <vector>

#include "util/error.h"
#include "util/file_names.h"
#include "util/quoted.h"

namespace layermod {
namespace {

constexpr std::size_t kMaxHeaderBytes = 64 * 1024;

struct PlyElement {
  std::string name;
  std::uint64_t count = 0;
  std::uint64_t min_row_bytes = 0;  // fixed properties plus one count byte per list
};

struct HeaderLines {
  std::vector<std::string> lines;  // after the magic line, up to end_header (excluded)
  std::uint64_t file_bytes = 0;
};

// Bytes of a scalar PLY type, 0 for an unknown name.
int TypeBytes(const std::string& type) {
  static const std::array<std::pair<const char*, int>, 16> kTypes = {{
      {"char", 1},
      {"uchar", 1},
      {"int8", 1},
      {"uint8", 1},
      {"short", 2},
      {"ushort", 2},
      {"int16", 2},
      {"uint16", 2},
      {"int", 4},
      {"uint", 4},
      {"int32", 4},
      {"uint32", 4},
      {"float", 4},
      {"float32", 4},
      {"double", 8},
      {"float64", 8},
  }};
  for (const auto& [name, bytes] : kTypes) {
    if (type == name) return bytes;
  }
  return 0;
}

// Reads the header lines; false when the file is not PLY at all. What assimp would read as
// PLY (a .ply name, or contents starting with "ply") must have exactly "ply" as its first line.
bool ReadHeaderLines(const std::filesystem::path& path, HeaderLines& header) {
  std::ifstream in(path, std::ios::binary);
  std::array<char, 3> start{};
  in.read(start.data(), start.size());
  const bool starts_with_ply = in.gcount() == 3 && std::string_view(start.data(), 3) == "ply";
  if (!starts_with_ply && LowercaseExtension(path) != ".ply") return false;
  in.clear();
  in.seekg(0);
  std::string magic;
  if (!std::getline(in, magic) || (magic != "ply" && magic != "ply\r")) {
    throw FormatError(Quoted(path) + ": not a PLY file (its first line must be \"ply\")");
  }
  std::size_t read = magic.size() + 1;
  for (std::string line; std::getline(in, line);) {
    read += line.size() + 1;
    if (!line.empty() && line.back() == '\r') line.pop_back();
    if (line == "end_header") {
      header.file_bytes = std::filesystem::file_size(path);
      header.file_bytes -= std::min<std::uint64_t>(header.file_bytes, read);
      return true;
    }
    if (read > kMaxHeaderBytes) break;
    header.lines.push_back(line);
  }
  throw FormatError(Quoted(path) + ": PLY header has no end_header line (truncated or not PLY)");
}

class HeaderParser {
 public:
  HeaderParser(const std::filesystem::path& path) : path_(path) {}

  void Parse(const std::vector<std::string>& lines) {
    for (std::size_t i = 0; i < lines.size(); ++i) ParseLine(lines[i], i + 2);
    if (format_.empty()) Fail(2, "PLY header has no format line");
  }

  bool binary() const { return format_ != "ascii"; }
  const std::vector<PlyElement>& elements() const { return elements_; }

 private:
  [[noreturn]] void Fail(std::size_t line_number, const std::string& problem) const {
    throw FormatError(Quoted(path_) + ": line " + std::to_string(line_number) + ": " + problem);
  }

  void ParseLine(const std::string& line, std::size_t number) {
    std::istringstream words(line);
    std::string keyword;
    words >> keyword;
    if (keyword == "comment" || keyword == "obj_info" || keyword.empty()) return;
    if (keyword == "format") return ParseFormat(words, number);
    if (keyword == "element") return ParseElement(words, number);
    if (keyword == "property") return ParseProperty(words, number);
    Fail(number, "unknown PLY header keyword " + Quoted(std::string_view(keyword)));
  }

  void ParseFormat(std::istringstream& words, std::size_t number) {
    std::string version;
    words >> format_ >> version;
    if (format_ != "ascii" && format_ != "binary_little_endian" && format_ != "binary_big_endian") {
      Fail(number, "unknown PLY format " + Quoted(std::string_view(format_)));
    }
    if (version != "1.0")
      Fail(number, "unsupported PLY version " + Quoted(std::string_view(version)));
  }

  void ParseElement(std::istringstream& words, std::size_t number) {
    PlyElement element;
    std::string count;
    words >> element.name >> count;
    const auto result = std::from_chars(count.data(), count.data() + count.size(), element.count);
    if (element.name.empty() || result.ec != std::errc() ||
        result.ptr != count.data() + count.size()) {
      Fail(number, "element needs a name and a count");
    }
    elements_.push_back(element);
  }

  void ParseProperty(std::istringstream& words, std::size_t number) {
    if (elements_.empty()) Fail(number, "property before any element");
    std::string type;
    words >> type;
    if (type == "list") {
      std::string count_type, item_type;
      words >> count_type >> item_type;
      if (TypeBytes(count_type) == 0 || TypeBytes(item_type) == 0) {
        Fail(number, "unknown PLY list types " + Quoted(std::string_view(count_type)) + " " +
                         Quoted(std::string_view(item_type)));
      }
      elements_.back().min_row_bytes += static_cast<std::uint64_t>(TypeBytes(count_type));
      return;
    }
    if (TypeBytes(type) == 0)
      Fail(number, "unknown PLY property type " + Quoted(std::string_view(type)));
    elements_.back().min_row_bytes += static_cast<std::uint64_t>(TypeBytes(type));
  }

  const std::filesystem::path& path_;
  std::string format_;
  std::vector<PlyElement> elements_;
};

}  // namespace

void CheckPlyHeader(const std::filesystem::path& path, std::size_t max_triangles) {
  HeaderLines header;
  if (!ReadHeaderLines(path, header)) return;
  HeaderParser parser(path);
  parser.Parse(header.lines);
  long double min_body_bytes = 0;
  for (const PlyElement& element : parser.elements()) {
    if (element.name == "face" && element.count > max_triangles) {
      throw FormatError(Quoted(path) + ": declares " + std::to_string(element.count) +
                        " faces, more than the limit of " + std::to_string(max_triangles) +
                        " triangles" + "; decimate the mesh first");
    }
    min_body_bytes += static_cast<long double>(element.count) * element.min_row_bytes;
  }
  if (parser.binary() && min_body_bytes > static_cast<long double>(header.file_bytes)) {
    throw FormatError(Quoted(path) + ": PLY header declares more data than the file holds (" +
                      std::to_string(header.file_bytes) + " bytes after the header; truncated?)");
  }
}

}  // namespace layermod
