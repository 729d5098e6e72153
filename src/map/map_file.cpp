#include "sgtllc/map/map_file.h"

#include <algorithm>
#include <cerrno>
#include <cstring>
#include <filesystem>
#include <new>

#include "map_decode.h"
#include "map_encode.h"
#include "sgtllc/io/input_file.h"

namespace sgtllc::map {
namespace {

/// A map file read in order through stdio's buffer; its size is the one it had when opened.
class FileSource final : public detail::ByteSource {
 public:
  explicit FileSource(const std::string& path) : path_(path), file_(io::openForReading(path)) {
    std::error_code ec;
    size_ = std::filesystem::file_size(path, ec);
    if (ec) throw Error("cannot read " + path + ": " + ec.message());
  }
  size_t read(char* out, size_t n) override {
    const size_t got = std::fread(out, 1, n, file_.get());
    if (got < n && std::ferror(file_.get())) throw Error("cannot read " + path_ + ": " + std::strerror(errno));
    return got;
  }
  uint64_t size() const override { return size_; }

 private:
  std::string path_;
  io::FilePtr file_;
  uint64_t size_ = 0;
};

Map readFile(const std::string& path, RetrievalMethod method, MapLayout* layout) {
  std::error_code ec;
  if (std::filesystem::is_directory(path, ec)) {
    throw Error("cannot read map " + path + ": is a directory, not a map file");
  }
  FileSource file(path);
  try {
    return detail::decodeMapFrom(file, path, method, layout, io::loadableBytes());
  } catch (const std::bad_alloc&) {  // within the machine's memory but not within what is free now
    throw Error(path + ": out of memory while loading a map of " + std::to_string(file.size()) + " bytes");
  }
}

}  // namespace

void writeMapFile(const std::string& path, const Map& map, io::Overwrite overwrite) {
  io::checkOutputFile(path, overwrite);  // before encoding: a refused path costs nothing
  // Written from the pieces, the keys from the map's memory: no copy of a map of gigabytes (BENCHMARKS.md
  // "Retrieval at scale").
  const detail::EncodedMap bytes = detail::encodeMapPieces(map, path);
  io::writeFileAtomically(path, bytes.pieces(), overwrite);
}

Map readMapFile(const std::string& path, const Config& config, MapLayout* layout) {
  Map map = readFile(path, config.retrieval.method, layout);
  checkCompatible(map, config, path);
  return map;
}

Map readMapFile(const std::string& path, MapLayout* layout) { return readFile(path, RetrievalMethod::kBruteForce, layout); }

}  // namespace sgtllc::map
