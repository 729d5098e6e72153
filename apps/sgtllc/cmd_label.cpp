// `sgtllc label SCAN`: the geometric labeller's classes of one scan (docs/labeller.md), as a SemanticKITTI .label
// file and/or a PLY point cloud coloured by class, so a user can look at them.
#include <array>
#include <cstdio>
#include <iostream>
#include <memory>

#include "commands.h"
#include "common.h"
#include "sgtllc/io/kitti.h"
#include "sgtllc/io/kitti_write.h"
#include "sgtllc/io/ply.h"
#include "sgtllc/io/scan_file.h"
#include "sgtllc/label/geometric_labeller.h"

namespace sgtllc::cli {
namespace {

struct LabelOptions {
  std::string scan, out, ply, config;
  bool force = false;
};

/// ASCII PLY of the points coloured by class: SemanticKITTI's colours (io::classColor), ground in its road
/// magenta, dropped points grey.
std::string colouredPly(const std::vector<Eigen::Vector3f>& points, const label::Labelling& l) {
  std::string s = "ply\nformat ascii 1.0\ncomment sgtllc label: geometric labeller classes\nelement vertex " +
                  std::to_string(points.size()) +
                  "\nproperty float x\nproperty float y\nproperty float z\nproperty uchar red\nproperty uchar green\n"
                  "property uchar blue\nend_header\n";
  char buf[96];
  for (size_t i = 0; i < points.size(); ++i) {
    const std::array<uint8_t, 3> c = l.classes[i] >= 0 ? io::classColor(l.classes[i])
                                     : l.ground[i]     ? std::array<uint8_t, 3>{255, 0, 255}
                                                       : std::array<uint8_t, 3>{128, 128, 128};
    std::snprintf(buf, sizeof(buf), "%.4f %.4f %.4f %u %u %u\n", points[i].x(), points[i].y(), points[i].z(), c[0],
                  c[1], c[2]);
    s += buf;
  }
  return s;
}

void runLabel(const LabelOptions& o) {
  const Config config = loadConfigOption(o.config, 0, "geometric");
  if (o.out.empty() && o.ply.empty()) throw Error("nothing to write: give --out LABELS.label and/or --export FILE.ply");
  if (!o.out.empty()) checkWritable(o.out, o.force);
  if (!o.ply.empty()) checkWritable(o.ply, o.force);
  const std::vector<Eigen::Vector3f> points = io::readScanPoints(o.scan);
  const label::Labelling l = label::GeometricLabeller(config.labeller).classify(points);
  if (!o.out.empty()) io::writeLabelFile(o.out, label::semanticKittiIds(l), io::overwriteIf(o.force));
  if (!o.ply.empty()) writeOutput(o.ply, colouredPly(points, l), o.force);
  std::array<size_t, kNumPaperClasses> count{};
  size_t ground = 0, dropped = 0;
  for (size_t i = 0; i < points.size(); ++i) {
    if (l.classes[i] >= 0) {
      ++count[l.classes[i]];
    } else {
      ++(l.ground[i] ? ground : dropped);
    }
  }
  std::cout << o.scan << ": " << points.size() << " points, " << l.segments << " segments"
            << (l.ground_found ? "" : ", no ground found") << "\n";
  for (int c = 0; c < kNumPaperClasses; ++c) {
    if (c != kTrunk) std::cout << "  " << kClassNames[c] << (c == kPole ? " (and trunk)" : "") << " " << count[c] << "\n";
  }
  std::cout << "  ground " << ground << "\n  dropped " << dropped << "\n";
}

}  // namespace

void addLabelCommand(CLI::App& app) {
  auto o = std::make_shared<LabelOptions>();
  CLI::App* cmd = app.add_subcommand("label", "Label a scan from its geometry alone (SemanticKITTI .label, coloured PLY)");
  cmd->add_option("SCAN", o->scan, "KITTI .bin scan, or a .pcd or .ply (x, y, z; a label field is ignored)")->required();
  cmd->add_option("--out", o->out, "write SemanticKITTI raw ids (uint32 per point) to this .label file");
  cmd->add_option("--export", o->ply, "write the points coloured by class to this ASCII PLY file");
  cmd->add_option("--config", o->config, "YAML configuration (its labeller.* keys; see `sgtllc config`)");
  cmd->add_flag("--force", o->force, "overwrite existing output files");
  cmd->callback([o] { runLabel(*o); });
}

}  // namespace sgtllc::cli
