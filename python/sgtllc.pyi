"""Type stubs of the sgtllc module (python/*.cpp). One line per bound field: keep them in step with the bindings."""
from __future__ import annotations

from enum import Enum
from typing import Iterator, overload, MutableMapping, MutableSequence, Optional, Sequence, Tuple

import numpy as np
import numpy.typing as npt

__version__: str
ArrayLike = npt.ArrayLike
Nodes = Tuple[np.ndarray, np.ndarray]  # (centres (N, 3) float64, classes (N,) int32)

class Error(ValueError): ...
class ConfigError(Error):
    key: str

# --- configuration (config.cpp, config_backend.cpp) ---
class LabelPreset(Enum):
    SEMANTIC_KITTI_RAW: int; SEMANTIC_KITTI_LEARNING: int; MULRAN: int; MCD: int; CUSTOM: int; NUSCENES: int
class LabelFormat(Enum):
    AUTO: int; UINT32: int; UINT8: int
class CentreSource(Enum):
    POINTS: int; VOXELS: int
class CentreHeight(Enum):
    POINTS: int; SENSOR: int
class SubVectorOrder(Enum):
    PAPER: int; CODE: int
class GlobalMode(Enum):
    G1: int; G2: int; G3: int
class SubVectorKind(Enum):
    DOT_PRODUCTS: int; ANGLES: int; LENGTHS: int
class RetrievalMethod(Enum):
    BRUTE_FORCE: int; KD_TREE: int; IVF: int
class RetrievalKey(Enum):
    DISTANCE_HISTOGRAM: int; GLOBAL_DESCRIPTOR: int
class NodeScore(Enum):
    RATIO: int; COUNT: int
class ScoreFormula(Enum):
    PAPER: int; LEGACY: int; OVERLAP: int
class LabelSource(Enum):
    FILE: int; GEOMETRIC: int; HYBRID: int
class RefinementStatus(Enum):
    CONVERGED: int; MAX_ITERATIONS: int; TOO_FEW_POINTS: int; DEGENERATE: int; LOW_FITNESS: int; MOVED_TOO_FAR: int
class RobustLoss(Enum):
    NONE: int; HUBER: int; CAUCHY: int

class ExtraClass:
    name: str
    ids: Tuple[int, ...]
    def __init__(self, name: str, ids: Sequence[int] = ...) -> None: ...
class ExtraClassList(MutableSequence[ExtraClass]): ...
class CustomLabelMap(MutableMapping[int, int]): ...
class LabelConfig:
    preset: LabelPreset
    format: LabelFormat
    custom_map: CustomLabelMap
    extra_classes: ExtraClassList
    def num_classes(self) -> int: ...
    def class_name(self, c: int) -> str: ...
class ClassClusterConfig:
    voxel: float
    radius: float
    min_size: int
    centre_height: CentreHeight
    score_unmatched: bool
    def __init__(self, voxel: float = 0.0, radius: float = 1.0, min_size: int = 20,
                 centre_height: CentreHeight = ..., score_unmatched: bool = True) -> None: ...
class ClassClusterConfigList(MutableSequence[ClassClusterConfig]): ...
class ClusterConfig:
    classes: ClassClusterConfigList
    max_neighbors: int
    duplicate_radius: float
    centre: CentreSource
class GraphConfig:
    sigma_d: float
    max_nodes: int
    allow_k_equals_i: bool
class DescriptorConfig:
    kind: SubVectorKind
    order: SubVectorOrder
    global_mode: GlobalMode
class RetrievalConfig:
    key: RetrievalKey
    histogram_bins: int
    histogram_range: float
    num_candidates: int
    exclude_recent: int
    warmup_frames: int
    method: RetrievalMethod
    ivf_lists: int
    ivf_probe: int
    ivf_train_frames: int
class AssociationConfig:
    sigma_1: float
    max_delta_aj: float
    sigma_2: float
    score: NodeScore
    entries: int
class VerificationConfig:
    sigma_3: float
    min_associations: int
    ransac_iterations: int
    ransac_sample_size: int
    sample_with_replacement: bool
    inlier_threshold: float
    min_inliers: int
    min_inlier_fraction: float
    use_ransac: bool
    ransac_confidence: float
    score_formula: ScoreFormula
    score_covisible: bool
    max_tilt_deg: float
    guided_matching: bool
    consistency_pairs: int
    weak_inliers: int
    weak_min_footprint: float
    sigma_4: float
    select_margin: float
    lateral_distance: float
    neighbour_frames: int
    offset_decay_start: float
    offset_decay_end: float
    min_footprint_overlap: float
    max_seen_through: float
    footprint_search: float
    footprint_search_gain: float
    footprint_cell: float
    footprint_radius: float
    seed: int
class GroundConfig:
    sectors: int
    bin: float
    max_range: float
    min_range: float
    step: float
    max_slope: float
    max_climb: float
    tolerance: float
class SegmentRuleConfig:
    voxel: float
    min_points: int
    min_voxel_points: int
    pole_max_width: float
    pole_min_height: float
    pole_min_top: float
    pole_slice_low: float
    pole_slice_high: float
    pole_min_span: float
    pole_voxel: float
    pole_radius: float
    pole_max_occluded: float
    building_min_top: float
    building_min_length: float
    fence_max_top: float
    fence_min_length: float
    fence_max_width: float
    min_wall_share: float
    min_fence_wall_share: float
    min_scatter_share: float
class LabellerConfig:
    source: LabelSource
    ground: GroundConfig
    segments: SegmentRuleConfig
class RegistrationConfig:
    pair: bool
    online: bool
    ground_ids: Tuple[int, ...]
    voxel: float
    max_points: int
    match_voxel: float
    match_max_points: int
    normal_neighbors: int
    max_correspondence: float
    coarse_correspondence: float
    kernel: float
    max_iterations: int
    convergence: float
    min_fitness: float
    max_translation_change: float
    max_rotation_change_deg: float
    information_sigma_min: float
    information_scale: float
class OdometryNoise:
    translation_sigma_per_m: float
    translation_sigma_min: float
    rotation_sigma_per_m: float
    rotation_sigma_per_rad: float
    rotation_sigma_min: float
class LoopNoise:
    sigma_min: float
    information_scale: float
class LoopConsistency:
    translation_m: float
    translation_per_m: float
    rotation_rad: float
    rotation_per_m: float
class SolverSettings:
    num_threads: int
    max_iterations: int
    function_tolerance: float
    parameter_tolerance: float
    reduced_warm_start: bool
class OnlineSettings:
    reduced_graph: bool
    anchor_spacing_m: float
class SessionSettings:
    min_inter_loops: int
    keep_distance_m: float
    keep_heading_deg: float
    max_covering_sessions: int
class BackendConfig:
    odometry: OdometryNoise
    loops: LoopNoise
    loop_loss: RobustLoss
    loss_scale: float
    max_loop_chi2: float
    max_rejection_rounds: int
    consistency: LoopConsistency
    solver: SolverSettings
    online: OnlineSettings
    sessions: SessionSettings
    def validate(self) -> None: ...
class Config:
    labels: LabelConfig
    labeller: LabellerConfig
    cluster: ClusterConfig
    graph: GraphConfig
    descriptor: DescriptorConfig
    retrieval: RetrievalConfig
    registration: RegistrationConfig
    association: AssociationConfig
    verification: VerificationConfig
    threads: int
    backend: BackendConfig
    def num_classes(self) -> int: ...
    def add_class(self, extra: ExtraClass, cluster: ClassClusterConfig = ...) -> int: ...
    def validate(self) -> None: ...
    @staticmethod
    def from_yaml(path: str) -> Config: ...
    @staticmethod
    def from_yaml_string(yaml: str, source: str = "<config>") -> Config: ...
    def to_yaml(self) -> str: ...
    def reference(self) -> str: ...

# --- results (results.cpp) ---
class Rejection(Enum):
    NONE: int; FEW_ASSOCIATIONS: int; RANSAC_FAILED: int; FOOTPRINT_MISMATCH: int; SEEN_THROUGH: int

class SeenThrough:
    judged: int
    seen_through: int
    @property
    def share(self) -> float: ...
class FootprintOverlap:
    compared: int
    share: float
    seen: SeenThrough
class FootprintShift:
    shift: Tuple[float, float]
    compared: int
    share: float
    unshifted_share: float
class Search(Enum):
    SEARCHED: int; TOO_RECENT: int; WARMUP: int
class StageTimes:
    extraction_ms: float
    description_ms: float
    retrieval_ms: float
    verification_ms: float
    refinement_ms: float
    total_ms: float
class ExtractionStats:
    input_points: int
    nonfinite_points: int
    far_points: int
    unknown_label_points: int
    class_points: list[int]
    clusters: list[int]
    duplicates_suppressed: int
    capped_nodes: int
class NodeMatch:
    query: int
    match: int
    similarity: float
    guided: bool
class MatchResult:
    associations: list[NodeMatch]
    inliers: list[int]
    score_c: float
    score: float  # the loop score
    score_t: float  # the old name of score, kept one release
    rejection: Rejection
    T_match_query: np.ndarray  # (4, 4) float64, read-only view
    association_pairs: np.ndarray  # (K, 2) int32
    inlier_pairs: np.ndarray  # (n_in, 2) int32
    footprint: FootprintOverlap
    footprint_search: FootprintShift
    by_consistency: bool
class Refinement:
    status: RefinementStatus
    used: bool
    T_match_query_seed: np.ndarray  # (4, 4)
    T_match_query: np.ndarray  # (4, 4)
    iterations: int
    fitness: float
    rmse_m: float
    query_points: int
    match_points: int
    information: np.ndarray  # (6, 6)
    time_ms: float
class Candidate:
    frame: int
    distance2: float
    retrieved: bool
    match: MatchResult
    refinement: Optional[Refinement]
class FrameResult:
    frame: int
    num_nodes: int
    extraction: ExtractionStats
    search: Search
    candidates: list[Candidate]
    best: int
    is_loop: bool
    lateral: bool
    timing: StageTimes
    loop: Optional[Candidate]
    match_frame: int
    score: float
    score_t: float  # the old name of score, kept one release
    score_c: float
    T_match_query: np.ndarray
class PairResult:
    match: MatchResult
    is_loop: bool
    extraction_query: ExtractionStats
    extraction_match: ExtractionStats
    timing: StageTimes
    refinement: Optional[Refinement]
    query_nodes: Nodes
    match_nodes: Nodes
    score: float
    score_t: float  # the old name of score, kept one release
    score_c: float
    rejection: Rejection
    T_match_query: np.ndarray

# --- detector (detector.cpp) ---
class LoopDetector:
    num_frames: int
    config: Config
    @overload
    def __init__(self, config: Config = ...) -> None: ...
    @overload
    def __init__(self, map: Map, config: Config = ...) -> None: ...
    def process(self, points: ArrayLike, labels: ArrayLike, drop_nonfinite: bool = False) -> FrameResult: ...
    def process_nodes(self, centres: ArrayLike, classes: ArrayLike) -> FrameResult: ...
    def first_searched_frame(self) -> int: ...
    def nodes(self, frame: int) -> Nodes: ...
    def to_map(self, names: Optional[Sequence[str]] = None, poses: Optional[ArrayLike] = None) -> Map: ...
def compare_pair(query_points: ArrayLike, query_labels: ArrayLike, match_points: ArrayLike, match_labels: ArrayLike,
                 config: Optional[Config] = None, drop_nonfinite: bool = False) -> PairResult: ...
def compare_nodes(query_centres: ArrayLike, query_classes: ArrayLike, match_centres: ArrayLike,
                  match_classes: ArrayLike, config: Optional[Config] = None) -> PairResult: ...

# --- maps (map.cpp) ---
class Map:
    num_frames: int
    names: list[str]
    has_poses: bool
    has_footprints: bool
    poses: Optional[np.ndarray]
    sessions: list[Tuple[str, int, int]]
    config: list[Tuple[str, str]]
    def nodes(self, frame: int) -> Nodes: ...
    def save(self, path: str, force: bool = False) -> None: ...
def load_map(path: str, config: Optional[Config] = None) -> Map: ...
class Relocalization:
    search: FrameResult
    map_frame: int
    localized: bool
    score: float
    T_mapframe_query: np.ndarray
    T_world_query: Optional[np.ndarray]
    tracked: bool
    weak_rotation: bool
class Relocalizer:
    def __init__(self, map: Map, config: Config = ..., num_candidates: int = 50,
                 max_rotation_uncertainty_deg: float = 5.0) -> None: ...
    def localize(self, points: ArrayLike, labels: ArrayLike, drop_nonfinite: bool = False) -> Relocalization: ...
    def localize_nodes(self, centres: ArrayLike, classes: ArrayLike) -> Relocalization: ...
class RelocalizationTracker:
    def __init__(self, relocalizer: Relocalizer, weak_sigma: float = 0.2, gate_m: float = 3.0,
                 max_speed_m_per_frame: float = 2.0, window: int = 10) -> None: ...
    def localize_nodes(self, centres: ArrayLike, classes: ArrayLike) -> Relocalization: ...
    def reset(self) -> None: ...

# --- the process (module.cpp) ---
def reuse_freed_memory(keep_bytes: int = 33554432) -> bool: ...  # call once, at start
def huge_page_heap(bytes: int = 67108864) -> bool: ...  # call once, at start, after reuse_freed_memory

# --- readers (io.cpp) ---
def label_scan(points: ArrayLike, config: LabellerConfig = ...) -> Tuple[np.ndarray, np.ndarray]: ...  # (N,) int8, (N,) uint8
def label_scan_ids(points: ArrayLike, config: LabellerConfig = ...) -> np.ndarray: ...  # (N,) uint32 SemanticKITTI ids
def apply_labeller(points: ArrayLike, labels: ArrayLike, config: Config) -> np.ndarray: ...  # (N,) uint32 ids as the node extraction sees them
def read_kitti_bin(path: str) -> np.ndarray: ...  # (N, 4) float32
def read_labels(path: str, point_count: Optional[int] = None,
                format: LabelFormat = LabelFormat.AUTO) -> np.ndarray: ...  # (N,) uint32
def read_scan_pairs(path: str) -> list[Tuple[str, str]]: ...
def default_label_path(bin_path: str) -> str: ...
def read_labeled_scan(bin_path: str, label_path: str = "",
                      format: LabelFormat = LabelFormat.AUTO) -> Tuple[np.ndarray, np.ndarray]: ...
def read_pcd(path: str, label_field: str = "label") -> Tuple[np.ndarray, np.ndarray]: ...
def read_pcd_points(path: str) -> np.ndarray: ...  # (N, 3) float32
def read_ply(path: str, label_field: str = "label") -> Tuple[np.ndarray, np.ndarray]: ...  # vertex x y z, label
def read_ply_points(path: str) -> np.ndarray: ...  # (N, 3) float32
# KITTI or TUM, LiDAR frame; KITTI: calib's Tr for cam0 poses, pose_frame "auto" | "lidar" | "cam0" (as --pose-frame)
def read_poses(path: str, calib: Optional[str] = None, pose_frame: str = "auto") -> np.ndarray: ...  # (N, 4, 4)
def read_calib(path: str) -> np.ndarray: ...  # (4, 4)
def lidar_poses(cam_poses: ArrayLike, Tr: ArrayLike) -> np.ndarray: ...
def read_nodes(path: str, config: Optional[Config] = None) -> Nodes: ...
def write_nodes(path: str, centres: ArrayLike, classes: ArrayLike, config: Optional[Config] = None,
                overwrite: bool = False) -> None: ...
class SequenceDir:
    dir: str
    scan_dir: str            # DIR/velodyne or DIR
    format: str              # 'bin', 'pcd' or 'ply'
    labels_in_scans: bool    # labels from the scans' 'label' field (PCD, PLY)
    def __init__(self, dir: str, labels_dir: str = "", read_labels: bool = True,
                 format: LabelFormat = LabelFormat.AUTO) -> None: ...
    def __len__(self) -> int: ...
    def scan_path(self, i: int) -> str: ...
    def bin_path(self, i: int) -> str: ...
    def label_path(self, i: int) -> str: ...
    def frame_name(self, i: int) -> str: ...
    def load(self, i: int) -> Tuple[np.ndarray, np.ndarray]: ...

# --- node repeatability and label agreement (repeatability.cpp) ---
class NodeRepeatability:
    nodes: np.ndarray        # (16,) int64 per class index
    repeated: np.ndarray
    other_class: np.ndarray
    @overload
    def share(self) -> float: ...
    @overload
    def share(self, class_index: int) -> float: ...
def node_repeatability(a_centres: ArrayLike, a_classes: ArrayLike, b_centres: ArrayLike, b_classes: ArrayLike,
                       T_b_a: ArrayLike, radius: float = 0.5, range: float = 40.0) -> NodeRepeatability: ...
class ClassAgreement:
    tp: np.ndarray           # (16,) int64 per class index
    fp: np.ndarray
    fn: np.ndarray
    def precision(self, class_index: int) -> float: ...
    def recall(self, class_index: int) -> float: ...
    def iou(self, class_index: int) -> float: ...
def label_agreement(predicted: ArrayLike, reference: ArrayLike, reference_labels: LabelConfig = ...) -> ClassAgreement: ...

# --- metrics (metrics.cpp) ---
class PrCurve:
    thresholds: np.ndarray
    precision: np.ndarray
    recall: np.ndarray
    positives: int
def precision_recall(scores: ArrayLike, positives: ArrayLike, positives_override: int = 0) -> PrCurve: ...
def f1_max(curve: PrCurve) -> float: ...
def recall_at_100_precision(curve: PrCurve) -> float: ...
def extended_precision(curve: PrCurve) -> float: ...
class PoseError:
    translation_m: float
    rotation_deg: float
    def __init__(self, translation_m: float = 0.0, rotation_deg: float = 0.0) -> None: ...
    def succeeds(self, max_translation_m: float, max_rotation_deg: float) -> bool: ...
def pose_error(estimate: ArrayLike, ground_truth: ArrayLike) -> PoseError: ...
class PoseSummary:
    evaluated: int
    successes: int
    success_rate: float
    rte_mean: float
    rre_mean: float
def summarise_poses(errors: Sequence[PoseError], max_translation_m: float = 2.0,
                    max_rotation_deg: float = 5.0) -> PoseSummary: ...
class ErrorStats:
    rmse: float
    mean: float
    median: float
    max: float
    count: int
class AteResult:
    aligned: ErrorStats
    unaligned: ErrorStats
    T_gt_est: np.ndarray
class RpeResult:
    delta_frames: int
    translation_m: ErrorStats
    rotation_deg: ErrorStats
class SegmentError:
    translation_percent: float
    rotation_deg_per_100m: float
    segments: int
def absolute_trajectory_error(ground_truth: ArrayLike, estimate: ArrayLike) -> AteResult: ...
def relative_pose_error(ground_truth: ArrayLike, estimate: ArrayLike, delta_frames: int = 1) -> RpeResult: ...
def kitti_segment_error(ground_truth: ArrayLike, estimate: ArrayLike, lengths_m: Sequence[float] = ...,
                        step_frames: int = 10) -> SegmentError: ...

# --- relocalization (relocalization.cpp; docs/relocalization.md) ---
class RelocalizationQuery:
    query_number: int
    map_frame: int
    accepted: bool
    score: float
    T_mapframe_query: np.ndarray
    def __init__(self, query_number: int, map_frame: int = -1, accepted: bool = False, score: float = 0.0,
                 T_mapframe_query: Optional[ArrayLike] = None) -> None: ...
class RelocalizationProtocol:
    positive_distance: float
    negative_distance: float
    max_translation_m: float
    max_rotation_deg: float
    def __init__(self) -> None: ...
class RelocalizationMetrics:
    queries: int
    positives: int
    negatives: int
    accepted: int
    accepted_near: int
    accepted_between: int
    accepted_far: int
    accepted_negatives: int
    pose_successes: int
    recall_at_1: Optional[float]
    precision: Optional[float]
    precision_no_between: Optional[float]
    pose_success: Optional[float]
    rte_mean_m: Optional[float]
    rre_mean_deg: Optional[float]
    false_rate: Optional[float]
    accepted_placed: int
    positives_placed: int
    precision_pose: Optional[float]
    recall_at_1_pose: Optional[float]
def relocalization_metrics(queries: Sequence[RelocalizationQuery], map_poses: ArrayLike, query_poses: ArrayLike,
                           protocol: RelocalizationProtocol = ...) -> RelocalizationMetrics: ...

# --- back end (backend.cpp) ---
class EdgeKind(Enum):
    ODOMETRY: int; LOOP: int
class LoopDecision(Enum):
    ACCEPTED: int; INCONSISTENT: int; LARGE_RESIDUAL: int
class Edge:
    from_: int
    to: int
    T_from_to: np.ndarray
    information: np.ndarray
    kind: EdgeKind
    def __init__(self, from_: int, to: int, T_from_to: ArrayLike, information: Optional[ArrayLike] = None,
                 kind: EdgeKind = ...) -> None: ...
class LoopReport:
    from_: int
    to: int
    decision: LoopDecision
    consistent_with: int
    chi2: float
class BackendResult:
    poses: np.ndarray
    loops: list[LoopReport]
    num_accepted: int
    num_rejected: int
    solves: int
    iterations: int
    final_cost: float
    converged: bool
    reduced: bool
    num_poses_solved: int
def odometry_information(T_prev_curr: ArrayLike, noise: OdometryNoise = ...) -> np.ndarray: ...
def loop_edge(match_frame: int, query_frame: int, match: MatchResult, query_nodes: Nodes, match_nodes: Nodes,
              noise: LoopNoise = ...) -> Edge: ...
class PoseGraphOptimizer:
    num_frames: int
    num_loops: int
    poses: np.ndarray
    result: BackendResult
    def __init__(self, config: BackendConfig = ..., T_world_first: Optional[ArrayLike] = None) -> None: ...
    def add_odometry(self, T_prev_curr: ArrayLike, information: Optional[ArrayLike] = None) -> int: ...
    def add_loop(self, loop: Edge) -> None: ...
    def close_loop(self, loop: Edge) -> BackendResult: ...
    def optimize(self) -> BackendResult: ...
    def optimize_reduced(self) -> BackendResult: ...

# --- scan accumulation (accumulate.cpp) ---
class ScanAccumulator:
    capacity: int
    points: int
    bytes: int
    def __init__(self, scans: int) -> None: ...
    def add(self, points: ArrayLike, labels: ArrayLike, T_world_scan: ArrayLike) -> Tuple[np.ndarray, np.ndarray]: ...
    def __len__(self) -> int: ...
    def clear(self) -> None: ...

# --- the loop-closing pipeline (pipeline.cpp; docs/pipeline.md) ---
class ClosingLoop:
    edge: Edge
    query: str
    match: str
    T_match_query: np.ndarray
    score: float
    score_c: float
    injected: bool
    has_information: bool
class Closing:
    result: BackendResult
    poses: np.ndarray
    ms: float
    final_ms: float
    online_solve_cpu_ms: list[float]
    online_final_shift_m: list[float]
class PipelineFrame:
    index: int
    detection: FrameResult
    loop: Optional[ClosingLoop]
    solved: bool
    update: Optional[BackendResult]
    solve_ms: float
class LoopClosingPipeline:
    poses: np.ndarray
    odometry: np.ndarray
    loops: list[ClosingLoop]
    names: list[str]
    num_frames: int
    config: Config
    def __init__(self, config: Config = ..., online: bool = False, accumulate: int = 1) -> None: ...
    def add_scan(self, points: ArrayLike, labels: Optional[ArrayLike] = None, pose: Optional[ArrayLike] = None,
                 name: str = "", drop_nonfinite: bool = False) -> PipelineFrame: ...
    def add_nodes(self, centres: ArrayLike, classes: ArrayLike, pose: Optional[ArrayLike] = None,
                  name: str = "") -> PipelineFrame: ...
    def finish(self) -> Closing: ...
    def to_map(self, poses: Optional[ArrayLike] = None) -> Map: ...
class SessionMerge:
    result: BackendResult
    placed: bool
    inter_loops: int
    inter_accepted: int
    T_world_odometry: np.ndarray
class SessionClosing:
    merge: SessionMerge
    ms: float
class SessionFrame:
    index: int
    detection: FrameResult
    loop: Optional[ClosingLoop]
    in_map: Relocalization
    inter: Optional[ClosingLoop]
class SessionPipeline:
    poses: np.ndarray
    loops: list[ClosingLoop]
    map_frames: int
    num_frames: int
    def __init__(self, map: Map, config: Config = ..., name: str = "session", map_session: str = "map") -> None: ...
    def add_scan(self, points: ArrayLike, labels: Optional[ArrayLike] = None, *, pose: ArrayLike, name: str = "",
                 drop_nonfinite: bool = False) -> SessionFrame: ...
    def add_nodes(self, centres: ArrayLike, classes: ArrayLike, pose: ArrayLike, name: str = "") -> SessionFrame: ...
    def add_loop(self, edge: Edge, query: str = "", match: str = "", *, injected: bool = False) -> None: ...
    def finish(self) -> SessionClosing: ...
    def merged_map(self) -> Map: ...
