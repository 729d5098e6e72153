// The `backend.*` keys of the configuration YAML (config_fields.cpp), kept apart so the back end's settings live in
// one place. config_fields.cpp owns the field machinery and passes it in as the makers below.
#pragma once

#include <cstdint>
#include <functional>
#include <string>
#include <utility>
#include <vector>

#include "sgtllc/config.h"

namespace sgtllc::io::detail {

/// How config_fields.cpp adds one field of each kind (key, comment, reference to the value).
struct BackendFieldMakers {
  std::function<void(std::string, std::string, std::function<double&(Config&)>)> number;
  std::function<void(std::string, std::string, std::function<int&(Config&)>)> integer;
  std::function<void(std::string, std::string, std::function<backend::RobustLoss&(Config&)>,
                     std::vector<std::pair<std::string, backend::RobustLoss>>)>
      loss;
  std::function<void(std::string, std::string, std::function<bool&(Config&)>)> boolean;
  /// A list of raw label ids, e.g. [40, 48] (registration.ground_ids).
  std::function<void(std::string, std::string, std::function<std::vector<uint32_t>&(Config&)>)> ids;
};

/// Adds every field of backend::BackendConfig, in struct order, with keys mirroring the struct.
void addBackendFields(const BackendFieldMakers& add);

/// Adds every field of RegistrationConfig (`registration.*`, config_yaml_registration.cpp) with the same makers.
void addRegistrationFields(const BackendFieldMakers& add);

/// Adds the numeric fields of LabellerConfig (`labeller.ground.*`, `labeller.segments.*`,
/// config_yaml_labeller.cpp); `labeller.source` is config_fields.cpp's.
void addLabellerFields(const BackendFieldMakers& add);

}  // namespace sgtllc::io::detail
