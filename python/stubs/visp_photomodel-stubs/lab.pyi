"""The simulated lab: the catalogue's toys rendered at a pose, their models, the servo loop."""
from typing import List, Tuple

from visp_photomodel import Image, PhotoModel, Pose, StereoRig, TrackResult

class Scene:
    """The lab's scene of one toy of the catalogue (pm::sim::Scene): what the rig's cameras see for a pose of the toy."""
    def __init__(self, target: str = "C12", seed: int = 1) -> None:
        """target: C01..C12 (the paper's sea creatures) or R1..R3 (box, head, tower); seed: the cameras' noise. Raises
        Error for an unknown target."""
    def render(self, rig: StereoRig, hMo: Pose, frame: int = 0) -> Tuple[Image, Image]:
        """The stereo pair (left, right: H x W x 4 RGBA uint8) of the toy at hMo in the hand frame (4 x 4, metres);
        frame: the frame number (the noise changes with it)."""
    def make_model(self, rig: StereoRig, arm: str = "pa10") -> Tuple[PhotoModel, Pose]:
        """The toy's all-around model as a user makes it: the arm ('pa10', 'viper850', 'afma6') walks the rig around
        it. Returns (model, oMm): oMm, the model frame in the toy's (ground truth: hMm = hMo @ oMm)."""

class ServoFrame:
    """What one step of the servo loop did (pm::lab::LoopFrame)."""
    @property
    def t(self) -> float:
        """Time of the frame (s)."""
    @property
    def moving(self) -> bool:
        """The TC-robot moves the target."""
    @property
    def true_pose(self) -> Pose:
        """The model in the hand frame, true (4 x 4, m)."""
    @property
    def used_pose(self) -> Pose:
        """The pose the servo used (4 x 4, m)."""
    @property
    def result(self) -> TrackResult:
        """The tracker's TrackResult."""
    @property
    def servoing(self) -> bool:
        """The servo ran on the estimate (else the arm was being stopped)."""
    @property
    def error_mm(self) -> float:
        """The hand against where it should be: translation (mm)."""
    @property
    def error_deg(self) -> float:
        """... and rotation (deg)."""
    @property
    def estimate_error_mm(self) -> float:
        """The tracker's estimate against the truth (mm)."""
    @property
    def estimate_error_deg(self) -> float:
        """... (deg)."""
    @property
    def servoed_on_wrong_pose(self) -> bool:
        """The servo ran on a pose over 20 mm or 5 deg off (never, so far)."""
    @property
    def joints(self) -> List[float]:
        """The arm's joints after the frame (rad or m)."""

class ServoLoop:
    """The main job, frame by frame: the TC-robot moves the toy through Table 2's steps, the arm servoes on the
    tracker's pose (pm::lab::ClosedLoop). The toy's model is made first by the arm's pass (a few seconds).

        loop = lab.ServoLoop('C12', rig, data_path('trajectories/table2.csv'), seed=1)
        frame = loop.step(); left, right = loop.images()
    """
    def __init__(self, target: str, rig: StereoRig, trajectory: str, steps: int = 0, seed: int = 1, ga_seed: int = 1,
                 arm: str = "pa10") -> None:
        """target: a catalogue code; rig: the stereo rig; trajectory: the waypoints file
        (data_path('trajectories/table2.csv')); steps: its first N (0: all); seed: the cameras' noise; ga_seed: RM-GA's;
        arm: 'pa10', 'viper850' or 'afma6'. The same as pm-servo --target T --seed S --ga-seed G --robot A."""
    def step(self) -> ServoFrame:
        """One camera frame: images, estimate, command, the arm moved to the next frame."""
    def images(self) -> Tuple[Image, Image]:
        """The stereo pair of the last step() (left, right: H x W x 4 RGBA uint8 copies)."""
    @property
    def model(self) -> PhotoModel:
        """The toy's photo-model the pass made."""
    @property
    def time(self) -> float:
        """The time of the next step()'s frame (s)."""
    @property
    def duration(self) -> float:
        """The trajectory's duration (s): step() until then."""
