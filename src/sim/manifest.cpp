// simulation.txt (include/sgtllc/sim/manifest.h): written with every simulated sequence, read by a second session.
#include "sgtllc/sim/manifest.h"

#include <algorithm>
#include <charconv>
#include <filesystem>
#include <fstream>
#include <map>
#include <sstream>
#include <system_error>
#include <vector>

#include "sgtllc/io/quote.h"
#include "sgtllc/types.h"

namespace sgtllc::sim {
namespace {

constexpr const char* kFirst = "first.";

template <typename T>
std::string number(T value) {
  char buf[64];
  const auto [end, ec] = std::to_chars(buf, buf + sizeof(buf), value);  // shortest exact form, locale-free
  return ec == std::errc() ? std::string(buf, end) : std::string("?");
}

void appendSettings(std::string& out, const SimConfig& c, const std::string& prefix) {
  out += prefix + "frames " + number(c.frames) + "\n";
  out += prefix + "seed " + number(c.seed) + "\n";
  out += prefix + "scene " + sceneName(c.scene) + "\n";
  out += prefix + "sensor " + sensorName(c.sensor.kind) + "\n";
  out += prefix + "accumulate " + number(c.accumulate) + "\n";
  out += prefix + "label_noise " + number(c.label_noise) + "\n";
  out += prefix + "revisits " + number(c.revisits) + "\n";
  out += prefix + "sensor_height " + number(c.sensor_height) + "\n";
}

/// The key–value lines of a manifest, with the line each came from.
class Entries {
 public:
  Entries(const std::string& text, const std::string& path) : path_(path) {
    std::istringstream in(text);
    std::string line;
    for (int n = 1; std::getline(in, line); ++n) {
      if (!line.empty() && line.back() == '\r') line.pop_back();
      if (line.empty() || line[0] == '#') continue;
      const size_t space = line.find(' ');
      if (space == std::string::npos || space == 0 || space + 1 == line.size()) {
        throw Error(where(n) + "expected 'key value', got " + io::quoteContent(line));
      }
      const std::string key = line.substr(0, space);
      if (!values_.emplace(key, std::make_pair(line.substr(space + 1), n)).second) {
        throw Error(where(n) + io::quoteContent(key) + " appears twice");
      }
    }
  }

  bool has(const std::string& key) const { return values_.count(key) != 0; }

  std::string text(const std::string& key) {
    const auto it = values_.find(key);
    if (it == values_.end()) throw Error(path_ + ": '" + key + "' is missing");
    used_.push_back(key);
    line_ = it->second.second;
    return it->second.first;
  }

  template <typename T>
  T get(const std::string& key) {
    const std::string v = text(key);
    T value{};
    const auto [end, ec] = std::from_chars(v.data(), v.data() + v.size(), value);
    if (ec != std::errc() || end != v.data() + v.size()) throw bad(key, v);
    return value;
  }

  /// A value read by @p parse, which throws sgtllc::Error for a bad one.
  template <typename Parse>
  auto parse(const std::string& key, Parse&& parse) {
    const std::string v = text(key);
    try {
      return parse(v);
    } catch (const Error&) {
      throw bad(key, v);
    }
  }

  Error bad(const std::string& key, const std::string& value) const {
    return Error(where(line_) + io::quoteContent(value) + " is not a valid " + key);
  }

  /// Throws for the first key nothing read.
  void checkAllUsed() const {
    for (const auto& [key, value] : values_) {
      if (std::find(used_.begin(), used_.end(), key) == used_.end()) {
        throw Error(where(value.second) + "unknown key " + io::quoteContent(key));
      }
    }
  }

 private:
  std::string where(int line) const { return path_ + ": line " + std::to_string(line) + ": "; }

  std::string path_;
  std::map<std::string, std::pair<std::string, int>> values_;
  std::vector<std::string> used_;
  int line_ = 0;
};

SimConfig readSettings(Entries& e, const std::string& prefix) {
  SimConfig c;
  c.frames = e.get<int>(prefix + "frames");
  c.seed = e.get<uint64_t>(prefix + "seed");
  c.scene = e.parse(prefix + "scene", parseSceneKind);
  c.sensor = SensorConfig::preset(e.parse(prefix + "sensor", parseSensorKind));
  c.accumulate = e.get<int>(prefix + "accumulate");
  c.label_noise = e.get<double>(prefix + "label_noise");
  c.revisits = e.get<int>(prefix + "revisits");
  c.sensor_height = e.get<double>(prefix + "sensor_height");
  return c;
}

}  // namespace

std::string manifestText(const SimConfig& config) {
  std::string out = "# sgtllc simulate: the settings this sequence was written with (read by simulate --world-of)\n";
  out += "format " + number(kManifestFormat) + "\n";
  appendSettings(out, config, "");
  if (config.world_of) appendSettings(out, *config.world_of, kFirst);
  if (config.follow) out += "follow 1\n";  // only when set: manifests written before it stay as they were
  return out;
}

SimConfig parseManifest(const std::string& text, const std::string& path) {
  Entries e(text, path);
  const int format = e.get<int>("format");
  if (format > kManifestFormat) {
    throw Error(path + ": format " + std::to_string(format) + " is newer than this sgtllc reads (" +
                std::to_string(kManifestFormat) + "); use a newer sgtllc");
  }
  if (format < 1) throw e.bad("format", std::to_string(format));
  SimConfig c = readSettings(e, "");
  if (e.has(std::string(kFirst) + "frames")) c.world_of = std::make_shared<SimConfig>(readSettings(e, kFirst));
  if (e.has("follow")) {
    const int follow = e.get<int>("follow");
    if (follow != 0 && follow != 1) throw e.bad("follow", std::to_string(follow));
    c.follow = follow == 1;
  }
  e.checkAllUsed();
  try {
    c.validate();
  } catch (const Error& error) {
    throw Error(path + ": " + error.what());
  }
  return c;
}

void writeManifest(const std::string& dir, const SimConfig& config, io::Overwrite overwrite) {
  io::writeFileAtomically(dir + "/" + kManifestName, manifestText(config), overwrite);
}

SimConfig readManifest(const std::string& dir) {
  const std::string path = dir + "/" + kManifestName;
  std::error_code ec;
  if (!std::filesystem::is_directory(dir, ec)) throw Error(dir + " is not a folder");
  if (!std::filesystem::exists(path, ec)) {
    throw Error(dir + " has no " + kManifestName + ": it is not a simulated sequence, or one written by an sgtllc "
                "older than the manifest; simulate it again with this sgtllc (the same --frames, --seed and --scene "
                "give the same files) to use it as a first session");
  }
  std::ifstream in(path, std::ios::binary);
  std::ostringstream text;
  text << in.rdbuf();
  if (!in && !in.eof()) throw Error("cannot read " + path);
  return parseManifest(text.str(), path);
}

}  // namespace sgtllc::sim
