"""Type stubs of the `linework` extension module (python/*.cpp); copied beside the module."""
from os import PathLike
from typing import Any, Iterator, Literal, Optional, Sequence, Tuple, TypedDict, Union, overload

import numpy as np
import numpy.typing as npt

__version__: str

StrPath = Union[str, PathLike[str]]
Vec3 = Union[Sequence[float], npt.NDArray[Any]]
Device = Union[Literal["auto", "cpu", "gpu"], str]

def read_image(path: StrPath) -> npt.NDArray[np.uint8]:
    """An image file as H×W×4 uint8, as the command line reads it."""

def write_png(path: StrPath, image: npt.ArrayLike) -> None:
    """Write an H×W×4 (or ×3, or grey) uint8 array as a PNG."""

def load_mesh(path: StrPath) -> Tuple[npt.NDArray[np.float32], npt.NDArray[np.int32], npt.NDArray[np.float32]]:
    """(vertices N×3, faces M×3, normals N×3) of a .gltf/.glb in world space, rest pose."""

class Polyline:
    """One run of a brush path: the SVG's <polyline> (closed loops without the repeated point)."""
    points: npt.NDArray[np.float32]    # N×2 pixels, x right, y down
    visible: npt.NDArray[np.bool_]     # N
    fade: npt.NDArray[np.float32]      # N
    depth: npt.NDArray[np.float32]     # N, eye depth
    s: npt.NDArray[np.float32]         # N, screen arc length, pixels
    position: npt.NDArray[np.float32]  # N×3, world
    closed: bool
    qi: int                            # occlusion level: 0 visible, else surfaces in front (1 unless counted)
    type: str
    line_set: str
    def __len__(self) -> int: ...

class FrameResult:
    index: int
    seconds: float
    image: Optional[npt.NDArray[np.uint8]]
    depth: Optional[npt.NDArray[np.float32]]
    lines: Optional[dict[str, list[Polyline]]]
    timings: dict[str, float]

class Snapshot:
    seconds: float

class FrameIterator(Iterator[FrameResult]):
    def __iter__(self) -> FrameIterator: ...
    def __next__(self) -> FrameResult: ...

class Session:
    """A scene made live, drawn as `linework render` draws it."""
    def __init__(
        self,
        scene: Union[StrPath, dict[str, Any], None] = None,
        *,
        device: Device = "auto",
        size: Optional[Tuple[int, int]] = None,
        eye: Optional[Vec3] = None,
        target: Optional[Vec3] = None,
        up: Optional[Vec3] = None,
        fov: Optional[float] = None,
        vertices: Optional[npt.ArrayLike] = None,
        faces: Optional[npt.ArrayLike] = None,
        normals: Optional[npt.ArrayLike] = None,
        name: str = "mesh",
        compute: Literal["auto", "device", "host"] = "auto",
        coherent: bool = False,
        validation: Optional[bool] = None,
    ) -> None: ...
    @overload
    def render(self, t: Optional[float] = None, *, frame: Optional[int] = None,
               depth: Literal[False] = False) -> npt.NDArray[np.uint8]: ...
    @overload
    def render(self, t: Optional[float] = None, *, frame: Optional[int] = None,
               depth: Literal[True]) -> Tuple[npt.NDArray[np.uint8], npt.NDArray[np.float32]]: ...
    def lines(self, t: Optional[float] = None, *, frame: Optional[int] = None,
              hidden: bool = False) -> dict[str, list[Polyline]]: ...
    def frame(self, t: Optional[float] = None, *, frame: Optional[int] = None, image: bool = True,
              depth: bool = False, lines: bool = True, hidden: bool = False) -> FrameResult: ...
    def frames(self, frames: Union[range, Tuple[int, int], None] = None, *, image: bool = True, depth: bool = False,
               lines: bool = False, hidden: bool = False, warmup: int = 0) -> FrameIterator: ...
    def snapshot(self) -> Snapshot: ...
    def restore(self, snapshot: Snapshot) -> None: ...
    @property
    def scene(self) -> dict[str, Any]: ...
    def configure(self, changes: dict[str, Any]) -> None: ...
    @property
    def size(self) -> Tuple[int, int]: ...
    @property
    def camera(self) -> dict[str, Any]: ...
    def set_camera(self, *, eye: Optional[Vec3] = None, target: Optional[Vec3] = None, up: Optional[Vec3] = None,
                   fov: Optional[float] = None, view: Optional[npt.ArrayLike] = None) -> None: ...
    def reset_camera(self) -> None: ...
    @property
    def view_matrix(self) -> npt.NDArray[np.float32]: ...
    @property
    def projection_matrix(self) -> npt.NDArray[np.float32]: ...
    @property
    def frame_range(self) -> Tuple[int, int]: ...
    @property
    def fps(self) -> float: ...
    @property
    def validation_messages(self) -> list[str]: ...

# --- synthesizers (python/synthesizers.cpp, python/synthesizers_2d.cpp) ----------------------

Image = npt.ArrayLike               # H×W, H×W×3 or H×W×4 uint8
Points = npt.ArrayLike              # N×2 float, output pixels / drawing units (x right, y down)

class StrokeDict(TypedDict, total=False):
    """A stroke in: the keys of a JSON stroke file; only "points" is required."""
    points: Points
    width: float                    # one width for every point (default 1), or:
    widths: npt.ArrayLike           # N widths
    color: Union[Sequence[float], str]  # (r, g, b) in [0, 1] or "#rrggbb" (default black)
    closed: bool

class Stroke(TypedDict):
    """A stroke out."""
    points: npt.NDArray[np.float32]  # N×2
    widths: npt.NDArray[np.float32]  # N
    color: Tuple[float, float, float]
    closed: bool

StrokesIn = Union[StrPath, Sequence[Union[Points, StrokeDict]]]  # a stroke file (SVG/JSON) or strokes

def slam(exemplar: Union[Image, StrPath], *, levels: int = 17, length: int = 1024, iterations: int = 15,
         seed: int = 1, global_statistics: bool = False, threads: int = 0) -> npt.NDArray[np.float32]:
    """SLAM synthesized from a stroke exemplar (Bénard et al. 2010 §3.2), as `linework slam`:
    float32 ink of shape (levels, exemplar rows, length), levels 0.5 … 1.0."""

def slam_pattern(name: Literal["dots", "dashes", "pencil"], *, levels: int = 17, length: int = 1024,
                 height: int = 32, seed: int = 1) -> npt.NDArray[np.float32]:
    """A procedural SLAM as `linework slam-pattern`: (levels, height, length) float32."""

def read_slam(path: StrPath) -> npt.NDArray[np.float32]:
    """A SLAM file (.exr) as (levels, height, length) float32."""

def write_slam(path: StrPath, ink: npt.ArrayLike, *, exemplar_name: str = "python", seed: int = 0) -> None:
    """Write (levels ≥ 2, height, length) ink in [0, 1] as a SLAM file (.exr)."""

@overload
def ribbon(exemplar: Union[Image, StrPath], curve: Union[Points, StrPath], *, closed: bool = False,
           piece: Optional[float] = None, width: Optional[float] = None, scale: Optional[float] = None,
           seed: int = 1, stitch: bool = False, size: Optional[Tuple[int, int]] = None,
           avoid: Union[Image, StrPath, None] = None, transparent: bool = False, reference: bool = False,
           device: Device = "auto", return_info: Literal[False] = False) -> npt.NDArray[np.uint8]:
    """A structured pattern along a curve (Zhou et al. 2013), as `linework ribbon` writes it:
    H×W×4 uint8 (over white unless transparent)."""
@overload
def ribbon(exemplar: Union[Image, StrPath], curve: Union[Points, StrPath], *, closed: bool = False,
           piece: Optional[float] = None, width: Optional[float] = None, scale: Optional[float] = None,
           seed: int = 1, stitch: bool = False, size: Optional[Tuple[int, int]] = None,
           avoid: Union[Image, StrPath, None] = None, transparent: bool = False, reference: bool = False,
           device: Device = "auto", return_info: Literal[True]) -> Tuple[npt.NDArray[np.uint8], dict[str, Any]]:
    """(image, info): info holds what --dump-dp writes (positions, seam_costs, total_cost,
    greedy_cost, random_cost, valid_counts, row_ms, pieces) and the width, piece, scale, size used."""

def ribbon_exemplar(name: Literal["chain", "lace", "zigzag", "beads", "rope"], *, width: int = 192,
                    height: int = 64, seed: int = 1) -> npt.NDArray[np.uint8]:
    """A procedural ribbon exemplar as `linework ribbon-exemplar`: H×W×4 uint8."""

@overload
def pattern(reference: StrokesIn, *, path: Union[Points, StrPath, None] = None,
            region: Union[Points, StrPath, None] = None, ref_path: Union[Points, StrPath, None] = None,
            ref_region: Union[Points, StrPath, None] = None, closed: bool = False, scale: Optional[float] = None,
            rings: Optional[int] = None, variation: float = 0.0, fit: Literal["contour", "skeleton"] = "contour",
            lloyd: int = 30, seed: int = 1, return_info: Literal[False] = False) -> list[Stroke]:
    """A stroke pattern like the reference along a path or in a region (Barla et al. 2006), as
    `linework pattern` writes it."""
@overload
def pattern(reference: StrokesIn, *, path: Union[Points, StrPath, None] = None,
            region: Union[Points, StrPath, None] = None, ref_path: Union[Points, StrPath, None] = None,
            ref_region: Union[Points, StrPath, None] = None, closed: bool = False, scale: Optional[float] = None,
            rings: Optional[int] = None, variation: float = 0.0, fit: Literal["contour", "skeleton"] = "contour",
            lloyd: int = 30, seed: int = 1, return_info: Literal[True]) -> Tuple[list[Stroke], dict[str, Any]]:
    """(strokes, info): info holds reference_elements, epsilon, rings, matched, fallback, source,
    centers, first_stroke and timings."""

@overload
def hatch(training: StrokesIn, *, count: int, window: int = 6, block: int = 50, threshold: Optional[float] = None,
          plausible: float = 0.5, along: Optional[StrokesIn] = None, seed: int = 1,
          return_info: Literal[False] = False) -> list[Stroke]:
    """A hatching sequence continued by example (Jodoin et al. 2002), as `linework hatch` writes it."""
@overload
def hatch(training: StrokesIn, *, count: int, window: int = 6, block: int = 50, threshold: Optional[float] = None,
          plausible: float = 0.5, along: Optional[StrokesIn] = None, seed: int = 1,
          return_info: Literal[True]) -> Tuple[list[Stroke], dict[str, Any]]:
    """(strokes, info): info holds blocks (index, first, last, window, kl2, attempts,
    over_threshold, as --kl2 prints them, and the block's own threshold), restarts,
    over_threshold, threshold (the full blocks'), training_strokes, dimensions."""
