"""visp-photomodel from Python: rigs and camera files, photo-models (loaded, saved, built from a pass of the hand),
the photo-model tracker on NumPy images (H x W x 3 BGR as OpenCV gives them, H x W x 4 RGBA as ViSP holds them),
and the simulated lab (stereo pairs of a toy at a pose, the servo loop frame by frame).

Poses are 4 x 4 NumPy arrays in metres (hMo: the model in the hand frame). Errors raise Error with the one-line
message the programs print after 'error: '. docs/tutorial-python.md walks through it.
"""
from typing import Any, Dict, List, Optional, Sequence, Tuple, Union, overload

import numpy as np
import numpy.typing as npt

from . import lab as lab

Image = npt.NDArray[np.uint8]
"""An image: uint8, C-contiguous, H x W x 3 (BGR) or H x W x 4 (RGBA)."""
Pose = npt.NDArray[np.float64]
"""A rigid transform: 4 x 4 float64, metres."""

class Error(RuntimeError):
    """What the programs report as 'error: ...': a bad file, a bad value, a model that does not fit the rig."""

def data_path(relative: str) -> str:
    """The path of a shipped data file (e.g. 'rig/pa10_stereo.json'): $PM_DATA_DIR, the source tree's data/, or the
    installed share/visp-photomodel/."""

class Camera:
    """A camera: its intrinsics, image size, lens and where it sits on the hand (pm::core::PinholeCamera)."""
    @property
    def name(self) -> str:
        """'left' or 'right' on a rig."""
    @property
    def width(self) -> int:
        """Image width (px)."""
    @property
    def height(self) -> int:
        """Image height (px)."""
    @property
    def px(self) -> float:
        """Focal length along u (px)."""
    @property
    def py(self) -> float:
        """Focal length along v (px)."""
    @property
    def u0(self) -> float:
        """Principal point, column (px)."""
    @property
    def v0(self) -> float:
        """Principal point, row (px)."""
    @property
    def distortion(self) -> List[float]:
        """The lens's coefficients in OpenCV's order (k1, k2, p1, p2[, k3...]); empty: a pinhole camera."""
    @property
    def hMc(self) -> Pose:
        """The camera in the hand frame (4 x 4, metres)."""

class StereoRig:
    """The two cameras on the robot's hand (pm::core::StereoRig); load_rig() reads one."""
    @property
    def left(self) -> Camera:
        """The left camera (camera 0)."""
    @property
    def right(self) -> Camera:
        """The right camera (camera 1)."""
    @property
    def baseline_mm(self) -> float:
        """Distance between the optical centres (mm)."""
    def save(self, path: str, xml_name: str = "", description: str = "") -> None:
        """Writes the rig JSON and its intrinsics XML (xml_name, relative to the JSON's folder; default: the JSON's
        stem + '.xml'). Nothing is left half-written."""

class CameraRig:
    """The cameras on the robot's hand, one to four (pm::core::CameraRig): camera k is rig[k] (a stereo rig: 0 left,
    1 right); load_camera_rig() reads one, and a StereoRig is taken wherever a CameraRig is."""
    @overload
    def __init__(self, stereo: StereoRig) -> None:
        """The stereo rig's two cameras: 0 left, 1 right."""
    @overload
    def __init__(self, cameras: Sequence[Camera]) -> None:
        """The rig of these cameras, in this order (one to four). Raises Error for none or more than four."""
    def __len__(self) -> int: ...
    def __getitem__(self, k: int) -> Camera: ...
    @property
    def cameras(self) -> List[Camera]:
        """The cameras, camera k at [k]."""

def load_camera_rig(path: str) -> CameraRig:
    """Reads a rig file of one to four cameras (data/rig/pa10_mono.json: one). Raises Error naming the file and what is
    wrong."""

def load_rig(path: str) -> StereoRig:
    """Reads a stereo rig file (rig.json, as pm-calibrate-rig writes it). Raises Error naming the file and what is wrong."""

def read_camera_file(path: str, name: str = "", width: int = 0, height: int = 0) -> Camera:
    """Reads one camera: a ViSP XML (name selects the camera), an OpenCV or a ROS YAML; width and height (0: any) the
    image size it must have."""

def write_camera_file(camera: Camera, path: str) -> None:
    """Writes the camera as an OpenCV YAML file (read back by read_camera_file())."""

def read_image(path: str) -> Image:
    """Reads a PNG, JPEG or PPM file as the programs do: an H x W x 4 RGBA uint8 array. Raises Error naming the file."""

def write_image(image: Image, path: str) -> None:
    """Writes an H x W x 4 RGBA or H x W x 3 BGR uint8 array as the programs do (PNG, JPEG or PPM by the extension)."""

class PhotoModel:
    """A photo-model (pm::core::PhotoModel): the target's hue sampled inside its outline (S_in) and a strip of background
    around it (S_out), from each of its viewpoints. load_model() reads one, build_model() makes one."""
    @property
    def viewpoints(self) -> int:
        """Viewing directions it holds."""
    @property
    def inner_points(self) -> int:
        """S_in points of its first view."""
    @property
    def outer_points(self) -> int:
        """S_out points of its first view."""
    @property
    def inner(self) -> npt.NDArray[np.float32]:
        """S_in of its first view: an N x 4 float32 array, x, y, z (mm, the model frame) and hue (deg)."""
    @property
    def outer(self) -> npt.NDArray[np.float32]:
        """S_out of its first view, the same way."""
    @property
    def all_around(self) -> bool:
        """Made from a pass around the target (else flat or stereo)."""
    @property
    def has_outlines(self) -> bool:
        """It holds outlines: the tracker's precise stage runs."""
    @property
    def background_hue_deg(self) -> float:
        """The background's hue in its photos (deg)."""
    @property
    def target_hue_deg(self) -> float:
        """The target's mean hue (deg)."""
    def save(self, path: str) -> None:
        """Writes model.json (the current version). Nothing is left half-written."""
    def to_json(self) -> str:
        """The model as the text of model.json."""

def load_model(path: str) -> PhotoModel:
    """Reads model.json (pm-make-model writes it). Raises Error naming the file and what is wrong (a model of another
    version says so)."""

class PassView:
    """One stop of the hand's pass around the target: a stereo pair, the same pair with the target removed, and the
    hand's pose."""
    def __init__(self, left: Image, right: Image, fMh: Pose, background_left: Optional[Image] = None,
                 background_right: Optional[Image] = None, name: str = "view") -> None:
        """left, right: uint8 images (H x W x 3 BGR or H x W x 4 RGBA); fMh: the hand in a fixed world frame (4 x 4,
        metres, from the robot); the backgrounds: the same pose, the target removed (not needed with
        build_model(backdrop_hue_deg=...))."""
    @property
    def name(self) -> str: ...
    @property
    def fMh(self) -> Pose:
        """The hand in the world frame (4 x 4, metres)."""
    @property
    def left(self) -> Image:
        """The left photo (a copy, H x W x 4 RGBA)."""
    @property
    def right(self) -> Image:
        """The right photo (a copy, H x W x 4 RGBA)."""

def build_model(rig: StereoRig, views: Sequence[PassView], backdrop_hue_deg: Optional[float] = None,
                refine_outlines: bool = False) -> PhotoModel:
    """The all-around photo-model from a pass of the hand (a list of PassView, at least 6): silhouettes, carving,
    surface, viewpoints (pm::model::buildAllAroundModel; a few seconds, the GIL released). backdrop_hue_deg: a plain
    backdrop of that hue (no background images needed). Raises Error naming the view and what is wrong."""

def build_model_from_folder(rig: StereoRig, folder: str, backdrop_hue_deg: Optional[float] = None,
                            refine_outlines: bool = False) -> PhotoModel:
    """The same from a views folder (left_NN.png, right_NN.png, background_*_NN.png, pose_fPh_NN.yaml), as
    pm-make-model --views does."""

class TrackState:
    """The tracker's state (an enumeration): SEARCHING (no lock yet), TRACKING (locked), LOST (the lock lost)."""
    SEARCHING: TrackState
    TRACKING: TrackState
    LOST: TrackState
    @property
    def name(self) -> str:
        """'SEARCHING', 'TRACKING' or 'LOST'."""
    @property
    def value(self) -> int:
        """0, 1 or 2."""

class TrackResult:
    """What the tracker says about a frame (pm::tracker::TrackResult)."""
    @property
    def pose(self) -> Pose:
        """hMo: the model in the hand frame (4 x 4, metres)."""
    @property
    def phi(self) -> Tuple[float, float, float, float, float, float]:
        """The same pose as the programs write it: x, y, z (mm) and the quaternion's vector e1, e2, e3."""
    @property
    def state(self) -> TrackState:
        """SEARCHING, TRACKING or LOST."""
    @property
    def fitness(self) -> float:
        """F, the stereo fitness at the pose."""
    @property
    def quality(self) -> float:
        """q, the normalised fitness."""
    @property
    def confidence(self) -> float:
        """In (0, 1): how likely the pose is within 2 cm and 5 deg."""
    @property
    def verified(self) -> bool:
        """The lock survived its challenger search."""
    @property
    def trusted(self) -> bool:
        """Tracking, verified and confident: a pose a robot may act on."""
    @property
    def visible_share(self) -> float:
        """Share of the model's points not found hidden (1: nothing hidden)."""
    @property
    def precise(self) -> bool:
        """The precise stage's pose is the frame's."""
    @property
    def sigma(self) -> Optional[Tuple[float, float, float, float, float, float]]:
        """The pose's 1-sigma along the hand's x, y, z (mm) and about them (deg), or None where it is not known."""
    @property
    def evaluations(self) -> int:
        """RM-GA's work this frame (whole evaluations)."""
    @property
    def compute_ms(self) -> float:
        """Time spent in the tracker (ms)."""
    @property
    def steps_ms(self) -> Dict[str, float]:
        """Where compute_ms went, step by step (ms): plan, search, challenge, refine, measure, judge, apply."""

class Tracker:
    """The photo-model tracker (pm::tracker::PhotoModelTracker): a stereo pair in, the pose of the model in the hand
    frame out, with its state, confidence, trust and uncertainty. It starts searching from scratch. One thread at a
    time per tracker (it releases the GIL while it tracks: other threads run, but must not call the same tracker).

        tracker = Tracker(rig, model)
        result = tracker.track(left, right)   # uint8, H x W x 3 BGR or H x W x 4 RGBA
        if result.trusted: act_on(result.pose)
    """
    def __init__(self, rig: Union[CameraRig, StereoRig], model: PhotoModel, config: str = "", seed: Optional[int] = None,
                 budget_evaluations: Optional[int] = None, params: Optional[Dict[str, Any]] = None) -> None:
        """config: a tracker configuration file (pm-track --config's; empty: the defaults every program uses); params:
        its keys as a dict, over the file's or the defaults (e.g. {'search': {'budget_evaluations': 400}}: the keys of
        docs/file-formats.md); seed: RM-GA's seed; budget_evaluations: the frame's search budget in evaluations (0: the
        wall-time budget). Raises Error if the rig, the model or the configuration is invalid (an unknown key named),
        or the model does not fit the rig."""
    def initialize(self) -> None:
        """Searches from scratch (state: searching)."""
    def init_from_pose(self, hMo: Pose) -> None:
        """Starts from a known pose (4 x 4, metres; state: tracking)."""
    @overload
    def track(self, images: Sequence[Image]) -> TrackResult:
        """One frame of a rig of any number of cameras: a list of one image per camera, in the rig's order, each as
        track(left, right) takes them. Raises Error for another number of images."""
    @overload
    def track(self, left: Image, right: Image) -> TrackResult:
        """One stereo frame: uint8 C-contiguous arrays, H x W x 3 BGR (OpenCV) or H x W x 4 RGBA (ViSP; read where it
        lies, no copy), of the rig's image size. The GIL is released while it runs. Raises TypeError for another dtype,
        ValueError for another shape or a non-contiguous array, Error for another image size."""
    def apply_hand_motion(self, hNowMhPrev: Pose) -> None:
        """The hand moved since the last frame: hNowMhPrev is the previous hand frame seen from the current one (4 x 4,
        metres, from the robot's odometry)."""
    @property
    def pose(self) -> Pose:
        """hMo of the last frame (4 x 4, metres)."""
    @property
    def state(self) -> TrackState:
        """The state after the last frame."""
    @property
    def last_result(self) -> TrackResult:
        """What the last track() returned."""
    @property
    def has_precise_stage(self) -> bool:
        """The precise stage runs (a model with outlines): the results carry a sigma."""
