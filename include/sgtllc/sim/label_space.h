/// @file label_space.h
/// @brief The ids a simulated sequence's label files are written in: SemanticKITTI raw ids (uint32, the default) or
///        nuScenes-lidarseg's class index (one byte a point, as data/nuscenes and configs/nuscenes.yaml read).
#pragma once

#include <cstdint>
#include <string>

namespace sgtllc::sim {

enum class LabelSpace { kSemanticKitti, kNuScenes };

/// Parses "semantickitti" or "nuscenes"; throws sgtllc::Error naming the value otherwise.
LabelSpace parseLabelSpace(const std::string& name);

/// nuScenes-lidarseg index (0..39, 32..39 the moving objects of the KITTI-layout conversions) of a SemanticKITTI
/// label word the simulator writes (instance bits ignored): as nuScenes has it, buildings, other structures, poles
/// and signs are static.manmade 28, vegetation and trunks static.vegetation 30; terrain 27, fence → barrier 9,
/// road and parking → driveable surface 24, sidewalk 26, other ground 25, car 17, truck 23, other vehicle 16,
/// person 2, other object 29, moving car 32, moving person 39, unlabelled and anything else noise 0.
uint8_t nuScenesId(uint32_t semantic_kitti_word);

/// Rewrites `DIR/labels/NNNNNN.label` of frames 0 .. @p frames − 1 (SemanticKITTI uint32, as the simulator wrote
/// them) as one nuScenes byte a point, each file replaced atomically. Throws sgtllc::Error naming the file.
void rewriteLabelsAsNuScenes(const std::string& dir, int frames);

}  // namespace sgtllc::sim
