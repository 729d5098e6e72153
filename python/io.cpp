// File readers (include/sgtllc/io/): KITTI scans, labels, poses and calib, PCD, node files, sequence folders.
// A missing file raises FileNotFoundError; a malformed one sgtllc.Error naming the file (and line) and the problem.
#include <filesystem>
#include <optional>

#include <pybind11/stl.h>

#include "arrays.h"
#include "bindings.h"
#include "opaque.h"
#include "sgtllc/io/kitti.h"
#include "sgtllc/io/nodes.h"
#include "sgtllc/io/pcd.h"
#include "sgtllc/io/ply_read.h"
#include "sgtllc/io/scan_pairs.h"
#include "sgtllc/io/sequence.h"
#include "sgtllc/io/trajectory.h"

namespace sgtllc::python {
namespace {

/// (N, 4) float32 x, y, z, intensity: the layout of the file, as np.fromfile(path, np.float32).reshape(-1, 4).
py::array_t<float> kittiBin(const std::string& path) {
  requireFile(path);
  std::vector<float> intensity;
  std::vector<Eigen::Vector3f> points;
  {
    py::gil_scoped_release release;
    points = io::readKittiBin(path, &intensity);
  }
  std::vector<float> xyzi(points.size() * 4);
  for (size_t i = 0; i < points.size(); ++i) {
    for (int k = 0; k < 3; ++k) xyzi[4 * i + k] = points[i][k];
    xyzi[4 * i + 3] = intensity[i];
  }
  return vectorToArray(std::move(xyzi), {static_cast<py::ssize_t>(points.size()), 4});
}

py::array_t<uint32_t> labelsArray(std::vector<uint32_t>&& labels) {
  const auto n = static_cast<py::ssize_t>(labels.size());
  return vectorToArray(std::move(labels), {n});
}

/// (points (N, 3) float32, labels (N,) uint32) of the scan @p read returns; the read runs without the GIL.
template <class Read>
py::tuple readCloud(const Read& read) {
  LabeledCloud cloud;
  {
    py::gil_scoped_release release;
    cloud = read();
  }
  return py::make_tuple(pointsToArray(std::move(cloud.points)), labelsArray(std::move(cloud.labels)));
}

/// read_poses: io::readTrajectory with the pose-frame rule, its note as a UserWarning.
py::array_t<double> readPoses(const std::string& path, const std::optional<std::string>& calib,
                              const std::string& pose_frame) {
  requireFile(path);
  if (calib) requireFile(*calib);
  const io::PoseFrame frame = io::parsePoseFrame(pose_frame);
  if (calib && frame == io::PoseFrame::kLidar) {
    throw Error(path + ": calib converts cam0 poses, pose_frame='lidar' says they are LiDAR poses: give one of them");
  }
  io::FramedTrajectory read;
  {
    py::gil_scoped_release release;
    read = io::readTrajectory(path, calib.value_or(""), frame);
  }
  if (!read.choice.note.empty() && PyErr_WarnEx(PyExc_UserWarning, read.choice.note.c_str(), 1) != 0) {
    throw py::error_already_set();  // warnings turned into errors
  }
  return posesToArray(read.trajectory.poses);
}

/// read_FORMAT(path, label_field="label") and read_FORMAT_points(path) over a point-cloud reader pair (PCD, PLY).
void bindCloudReaders(py::module_& m, const std::string& format,
                      LabeledCloud (*with_labels)(const std::string&, const std::string&),
                      std::vector<Eigen::Vector3f> (*points_only)(const std::string&), const std::string& doc,
                      const std::string& points_doc) {
  m.def(("read_" + format).c_str(),
        [with_labels](const std::string& path, const std::string& label_field) {
          requireFile(path);
          return readCloud([&] { return with_labels(path, label_field); });
        },
        py::arg("path"), py::arg("label_field") = "label",
        (doc + "Returns (points (N, 3) float32, labels (N,) uint32).").c_str());
  m.def(("read_" + format + "_points").c_str(),
        [points_only](const std::string& path) {
          requireFile(path);
          std::vector<Eigen::Vector3f> points;
          {
            py::gil_scoped_release release;
            points = points_only(path);
          }
          return pointsToArray(std::move(points));
        },
        py::arg("path"), (points_doc + "Returns points (N, 3) float32.").c_str());
}

/// Raises IndexError unless frame @p i is one of @p s's.
size_t frameIndex(const io::SequenceDir& s, py::ssize_t i) {
  const auto n = static_cast<py::ssize_t>(s.size());
  if (i < 0 || i >= n) {
    throw py::index_error("frame " + std::to_string(i) + " is out of range: the sequence has " + std::to_string(n) +
                          " frames" + (n > 0 ? " (0.." + std::to_string(n - 1) + ")" : std::string()));
  }
  return static_cast<size_t>(i);
}

}  // namespace

void bindIo(py::module_& m) {
  m.def("read_kitti_bin", &kittiBin, py::arg("path"),
        "Reads a KITTI velodyne scan as an (N, 4) float32 array: x, y, z (m), intensity.");
  m.def("read_labels",
        [](const std::string& path, std::optional<size_t> point_count, LabelFormat format) {
          requireFile(path);
          std::vector<uint32_t> labels;
          {
            py::gil_scoped_release release;
            // Without a point count only the file tells the size: uint8 takes every byte, else uint32 words.
            if (point_count) {
              labels = io::readLabelFile(path, *point_count, format);
            } else if (format == LabelFormat::kUint8) {
              labels = io::readLabelFile(path, static_cast<size_t>(std::filesystem::file_size(path)), format);
            } else {
              labels = io::readLabelFile(path);
            }
          }
          return labelsArray(std::move(labels));
        },
        py::arg("path"), py::arg("point_count") = py::none(), py::arg("format") = LabelFormat::kAuto,
        "Reads a label file as an (N,) uint32 array: SemanticKITTI uint32 words (semantic id = low 16 bits,\n"
        "instance = high 16) or one byte a point (nuScenes-lidarseg). With point_count, format AUTO tells the two\n"
        "apart by size and any other size raises; without it, AUTO and UINT32 read uint32 words.");
  m.def(
      "read_scan_pairs",
      [](const std::string& path) {
        std::vector<std::pair<std::string, std::string>> out;
        for (const io::ScanPair& p : io::readScanPairs(path)) out.emplace_back(p.query, p.match);
        return out;
      },
      py::arg("path"),
      "The pairs of a list file as `sgtllc pair --list` reads it: one pair a line, QUERY,MATCH as CSV (a path\n"
      "holding a comma quoted), `#` comments, an optional `query,match` header; relative paths are taken from the\n"
      "list's folder. Raises naming the file and line for a record of other than two paths, or a list with none.");
  m.def("default_label_path", &io::defaultLabelPath, py::arg("bin_path"),
        "The label file of a scan: DIR/../labels/NAME.label if it exists, else DIR/NAME.label.");
  m.def("read_labeled_scan",
        [](const std::string& bin_path, const std::string& label_path, LabelFormat format) {
          const std::string labels = label_path.empty() ? io::defaultLabelPath(bin_path) : label_path;
          requireFile(bin_path);
          requireFile(labels);
          return readCloud([&] { return io::readLabeledScan(bin_path, labels, format); });
        },
        py::arg("bin_path"), py::arg("label_path") = "", py::arg("format") = LabelFormat::kAuto,
        "Reads a scan and its labels (default: default_label_path; uint32 or one byte a point, see read_labels)\n"
        "and checks that there is one label a point.\n"
        "Returns (points (N, 3) float32, labels (N,) uint32).");
  bindCloudReaders(m, "pcd", &io::readPcd, &io::readPcdPoints,
                   "Reads x, y, z and a label field of a PCD file (ascii, binary or binary_compressed).\n",
                   "Reads x, y, z of a PCD file, with or without a label field (a raw scan for label_scan).\n");
  bindCloudReaders(m, "ply", &io::readPly, &io::readPlyPoints,
                   "Reads x, y, z and a label property of a PLY file's vertex element (ascii or binary).\n",
                   "Reads x, y, z of a PLY file's vertex element, with or without a label property.\n");
  m.def("read_poses", &readPoses, py::arg("path"), py::arg("calib") = py::none(), py::arg("pose_frame") = "auto",
        "Reads a trajectory, KITTI (12 columns) or TUM (8 columns), as (N, 4, 4) LiDAR-frame poses T_world_frame.\n"
        "The command line's rule and messages (--calib is calib=, --pose-frame is pose_frame=): a KITTI file goes\n"
        "through calib's Tr (cam0 poses, KITTI's poses.txt); pose_frame='lidar' takes it as LiDAR poses;\n"
        "'auto' without a calib lets the motion decide: LiDAR motion is read as such with a UserWarning saying so,\n"
        "cam0 motion or too little motion raises sgtllc.Error naming calib. TUM files are LiDAR poses.\n"
        "Rotations must be orthonormal (1e-3), TUM quaternions unit (1e-3), as for `sgtllc run --odometry`.");
  m.def("read_calib",
        [](const std::string& path) {
          requireFile(path);
          return matrixToArray(io::readKittiCalibTr(path));
        },
        py::arg("path"), "Reads the Tr line of a KITTI calib.txt (velodyne -> cam0) as a (4, 4) array.");
  m.def("lidar_poses",
        [](const ArrayLike& cam_poses, const ArrayLike& Tr) {
          return posesToArray(io::lidarPoses(posesFromArray(cam_poses, "cam_poses"), matrixFromArray(Tr, "Tr", 4, 4)));
        },
        py::arg("cam_poses"), py::arg("Tr"), "LiDAR-frame poses Tr^-1 P_i Tr of (N, 4, 4) cam0 poses.");
  m.def("read_nodes",
        [](const std::string& path, const Config* config) {
          requireFile(path);
          const LabelMap labels(config ? config->labels : LabelConfig{});
          return nodesToArrays(io::readNodesTxt(path, labels));
        },
        py::arg("path"), py::arg("config") = py::none(),
        "Reads a node file (`x y z label` rows, raw ids mapped with config.labels).\n"
        "Returns (centres (N, 3) float64, classes (N,) int32); rows of dropped classes are skipped.");
  m.def("write_nodes",
        [](const std::string& path, const ArrayLike& centres, const ArrayLike& classes, const Config* config,
           bool overwrite) {
          const LabelConfig labels = config ? config->labels : LabelConfig{};
          const std::vector<Node> nodes = nodesFromArrays(centres, classes, "", labels.numClasses());
          io::writeNodesTxt(path, nodes, labels, overwrite ? io::Overwrite::kReplace : io::Overwrite::kRefuse);
        },
        py::arg("path"), py::arg("centres"), py::arg("classes"), py::arg("config") = py::none(),
        py::arg("overwrite") = false,
        "Writes a node file that read_nodes reads back exactly. An existing file raises unless overwrite=True.");

  py::class_<io::SequenceDir>(m, "SequenceDir",
                              "A sequence folder: DIR/velodyne/NAME.bin (SemanticKITTI), or .bin, .pcd or .ply scans in\n"
                              "DIR itself (one format, name order), with labels from labels_dir/NAME.label, a PCD/PLY\n"
                              "'label' field, or DIR/labels/NAME.label (the command line's SEQ_DIR).")
      .def(py::init([](const std::string& dir, const std::string& labels_dir, bool read_labels, LabelFormat format) {
             if (!read_labels && !labels_dir.empty()) throw Error("labels_dir and read_labels=False exclude each other");
             return io::SequenceDir(dir, io::SequenceLabels{read_labels, labels_dir, format});
           }),
           py::arg("dir"), py::arg("labels_dir") = "", py::arg("read_labels") = true,
           py::arg("format") = LabelFormat::kAuto,
           "Lists the scans in file-name order; raises sgtllc.Error if there are none, the folder mixes formats,\n"
           "or a label file is missing. read_labels=False reads the scans alone (load gives no labels).")
      .def("__len__", &io::SequenceDir::size, "number of scans")
      .def_property_readonly("dir", &io::SequenceDir::dir, "the folder as given")
      .def_property_readonly("scan_dir", &io::SequenceDir::scanDir, "where the scans are: DIR/velodyne or DIR")
      .def_property_readonly("format", [](const io::SequenceDir& s) { return io::scanExtension(s.format()) + 1; },
                             "the scans' format: 'bin', 'pcd' or 'ply'")
      .def_property_readonly("labels_in_scans", &io::SequenceDir::labelsInScans,
                             "True when the labels come from the scans' 'label' field (PCD, PLY)")
      .def("scan_path", [](const io::SequenceDir& s, py::ssize_t i) { return s.scanPath(frameIndex(s, i)); },
           py::arg("i"), "the scan file of frame i (DIR/velodyne/NAME.bin, DIR/NAME.pcd, ...)")
      .def("bin_path", [](const io::SequenceDir& s, py::ssize_t i) { return s.scanPath(frameIndex(s, i)); },
           py::arg("i"), "scan_path(i), under its older name")
      .def("label_path",
           [](const io::SequenceDir& s, py::ssize_t i) {
             const size_t k = frameIndex(s, i);
             if (s.labelsInScans()) throw Error(s.scanPath(k) + ": the labels are in the scan's label field");
             return s.labelPath(k);
           },
           py::arg("i"), "DIR/labels/NAME.label of frame i (sgtllc.Error if the labels are in the scans)")
      .def("frame_name", [](const io::SequenceDir& s, py::ssize_t i) { return s.frameName(frameIndex(s, i)); },
           py::arg("i"), "file stem of frame i ('000052')")
      .def("load",
           [](const io::SequenceDir& s, py::ssize_t i) {
             const size_t k = frameIndex(s, i);
             return readCloud([&] { return s.load(k); });
           },
           py::arg("i"), "Reads frame i: (points (N, 3) float32, labels (N,) uint32).");
}

}  // namespace sgtllc::python
