// Simulated labels in nuScenes-lidarseg's ids (docs/algorithm.md §1 "nuScenes" says which of them sgtllc keeps).
#include "sgtllc/sim/label_space.h"

#include <cstdio>
#include <string_view>
#include <vector>

#include "sgtllc/io/kitti.h"
#include "sgtllc/io/output_file.h"
#include "sgtllc/sim/world.h"
#include "sgtllc/types.h"

namespace sgtllc::sim {

LabelSpace parseLabelSpace(const std::string& name) {
  if (name == "semantickitti") return LabelSpace::kSemanticKitti;
  if (name == "nuscenes") return LabelSpace::kNuScenes;
  throw Error("unknown label space '" + name + "' (expected semantickitti or nuscenes)");
}

uint8_t nuScenesId(uint32_t semantic_kitti_word) {
  using namespace semantic;
  switch (semantic_kitti_word & 0xFFFFu) {
    case kBuilding: case kOtherStructure: case kPole: case kTrafficSign: return 28;  // static.manmade
    case kVegetation: case kTrunk: return 30;                                         // static.vegetation
    case kTerrain: return 27;
    case kFence: return 9;  // movable_object.barrier, the fence-like class
    case kRoad: case kParking: return 24;
    case kSidewalk: return 26;
    case kOtherGround: return 25;
    case kCar: return 17;
    case kTruck: return 23;
    case kOtherVehicle: return 16;
    case kPerson: return 2;
    case kOtherObject: return 29;
    case kMovingCar: return 32;
    case kMovingPerson: return 39;
    default: return 0;  // noise
  }
}

void rewriteLabelsAsNuScenes(const std::string& dir, int frames) {
  for (int i = 0; i < frames; ++i) {
    char name[32];
    std::snprintf(name, sizeof(name), "%06d.label", i);
    const std::string path = dir + "/labels/" + name;
    const std::vector<uint32_t> words = io::readLabelFile(path);
    std::string bytes(words.size(), '\0');
    for (size_t k = 0; k < words.size(); ++k) bytes[k] = static_cast<char>(nuScenesId(words[k]));
    io::writeFileAtomically(path, bytes, io::Overwrite::kReplace);
  }
}

}  // namespace sgtllc::sim
