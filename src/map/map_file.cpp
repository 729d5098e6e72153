#include "sgtllc/map/map_file.h"

#include <filesystem>

#include "file_util.h"  // sgtllc_io's private readWholeFile: the one way files are read whole

namespace sgtllc::map {
namespace {

std::string mapBytes(const std::string& path) {
  std::error_code ec;
  if (std::filesystem::is_directory(path, ec)) {
    throw Error("cannot read map " + path + ": is a directory, not a map file");
  }
  return io::detail::readWholeFile(path);
}

}  // namespace

void writeMapFile(const std::string& path, const Map& map, io::Overwrite overwrite) {
  io::checkOutputFile(path, overwrite);  // before encoding: a refused path costs nothing
  io::writeFileAtomically(path, encodeMap(map, path), overwrite);
}

Map readMapFile(const std::string& path, const Config& config, MapLayout* layout) {
  Map map = decodeMap(mapBytes(path), path, config.retrieval.method, layout);
  checkCompatible(map, config, path);
  return map;
}

Map readMapFile(const std::string& path, MapLayout* layout) {
  return decodeMap(mapBytes(path), path, RetrievalMethod::kBruteForce, layout);
}

}  // namespace sgtllc::map
