#include "ivf_section.h"

#include <cmath>

namespace sgtllc::map::detail {

std::string encodeIvf(const IvfState& state, uint32_t dim) {
  std::string out;
  put<uint32_t>(out, static_cast<uint32_t>(state.lists));
  put<uint32_t>(out, static_cast<uint32_t>(state.trained_frames));
  put<uint32_t>(out, dim);
  out.append(reinterpret_cast<const char*>(state.centroids.data()), sizeof(float) * state.centroids.size());
  put<uint64_t>(out, state.list_of_frame.size());
  for (int32_t l : state.list_of_frame) put<int32_t>(out, l);
  return out;
}

IvfState readIvfState(Reader& r) {
  IvfState s;
  s.lists = static_cast<int>(r.get<uint32_t>());
  s.trained_frames = static_cast<int>(r.get<uint32_t>());
  const uint32_t dim = r.get<uint32_t>();
  if (s.lists < 1 || s.lists > 65536 || dim == 0 || dim > (1u << 20)) {
    r.fail("an inverted file of " + std::to_string(s.lists) + " lists of keys of " + std::to_string(dim));
  }
  const uint64_t centroid_floats = static_cast<uint64_t>(s.lists) * dim;
  if (centroid_floats > r.remaining() / sizeof(float)) r.fail("the centroids do not fit in the section");
  s.centroids.resize(static_cast<size_t>(centroid_floats));
  for (float& v : s.centroids) {
    v = r.get<float>();
    if (!std::isfinite(v)) r.fail("a centroid entry is not finite");
  }
  s.list_of_frame.resize(r.count(sizeof(int32_t)));
  for (int32_t& l : s.list_of_frame) {
    l = r.get<int32_t>();
    if (l < 0 || l >= s.lists) r.fail("a frame's list is out of range");
  }
  return s;
}

}  // namespace sgtllc::map::detail
