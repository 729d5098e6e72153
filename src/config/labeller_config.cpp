// The rules of the labeller settings beyond each one's range (config/labeller_config.h), and the label set the
// labelling stage gives.
#include <cmath>
#include <string>

#include "config_ranges.h"
#include "sgtllc/config.h"
#include "sgtllc/labels.h"

namespace sgtllc {

using namespace detail;

void detail::validateLabellerRules(const LabellerConfig& l, const LabelConfig& labels) {
  if (l.source != LabelSource::kFile && l.source != LabelSource::kGeometric && l.source != LabelSource::kHybrid) {
    throw ConfigError("labeller.source", "labeller.source: unknown value");
  }
  const GroundConfig& g = l.ground;
  // The grid holds 12 bytes per cell: at most 4 million cells (48 MB).
  const double cells = g.sectors * std::ceil(g.max_range / g.bin);
  if (cells > 4.0e6) {
    throw ConfigError("labeller.ground.bin", "labeller.ground.sectors * max_range / bin = " + text(cells) +
                                                 " ground cells is more than 4000000");
  }
  const SegmentRuleConfig& s = l.segments;
  if (!(s.pole_slice_high > s.pole_slice_low)) {
    throw ConfigError("labeller.segments.pole_slice_high", "labeller.segments.pole_slice_high = " +
                                                               text(s.pole_slice_high) +
                                                               " must be above labeller.segments.pole_slice_low");
  }
  if (l.source != LabelSource::kFile && !labels.extra_classes.empty()) {
    throw ConfigError("labeller.source", std::string("labeller.source ") +
                                             (l.source == LabelSource::kGeometric ? "geometric" : "hybrid") +
                                             " gives only the paper's seven classes; "
                                         "labels.extra_classes must be empty (it has " +
                                             std::to_string(labels.extra_classes.size()) + ")");
  }
}

LabelConfig effectiveLabelConfig(const LabelConfig& labels, const LabellerConfig& labeller) {
  switch (labeller.source) {
    case LabelSource::kGeometric:
      return LabelConfig{};
    case LabelSource::kHybrid:
      return hybridSplits(labels).any() ? LabelConfig{} : labels;
    default:
      return labels;
  }
}

LabelConfig effectiveLabelConfig(const Config& config) { return effectiveLabelConfig(config.labels, config.labeller); }

}  // namespace sgtllc
