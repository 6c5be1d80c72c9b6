// SPDX-License-Identifier: MIT
#pragma once

// A thin RAII layer over libzip working on memory buffers, used by the archive reader/writer
// (and by tests that build corrupt archives). Errors throw FormatError/Error WITHOUT a file name;
// the archive functions add it.

#include <cstdint>
#include <memory>
#include <optional>
#include <string>
#include <string_view>
#include <vector>

struct zip;

namespace layermod {

struct ZipEntry {
  std::string name;
  std::string data;
  bool compress = true;  // deflate; false: stored as is
};

// Builds a zip file in memory, entries in the given order. Throws Error on a libzip failure.
std::string WriteZip(const std::vector<ZipEntry>& entries);

struct ZipEntryInfo {
  std::string name;
  std::uint64_t size = 0;  // uncompressed, as declared by the container
  std::uint64_t compressed_size = 0;
  std::uint32_t crc32 = 0;  // of the uncompressed bytes, as declared
  std::int32_t method = 0;  // ZIP_CM_*
  bool encrypted = false;
  bool stored = false;  // no compression
};

// Read-only view of a zip file held in memory. `bytes` must outlive the reader.
class ZipReader {
 public:
  explicit ZipReader(std::string_view bytes);  // throws FormatError: not a zip, truncated...
  ~ZipReader();
  ZipReader(const ZipReader&) = delete;
  ZipReader& operator=(const ZipReader&) = delete;

  std::size_t EntryCount() const { return entries_.size(); }
  const ZipEntryInfo& Entry(std::size_t index) const { return entries_.at(index); }
  std::optional<std::size_t> Find(std::string_view name) const;

  // Reads a whole entry whose declared size must not exceed `max_size`. The bytes produced must
  // match the declared size and checksum. Throws FormatError naming the entry.
  std::string Read(std::size_t index, std::uint64_t max_size) const;

 private:
  std::string InflateWhole(std::size_t index) const;
  std::string ReadStreamed(std::size_t index) const;

  struct Discard {
    void operator()(zip* archive) const;
  };
  std::unique_ptr<zip, Discard> archive_;
  std::vector<ZipEntryInfo> entries_;
};

}  // namespace layermod
