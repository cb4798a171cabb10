// engine/coherence/still_paths.h — paths that did not move keep their parameterization.
//
// Under a still camera extraction gives the same paths frame after frame, but fitting a path
// to the splat again is not idempotent where paths crowd: its votes blend the T of its
// neighbours within the sprite radius (Bénard et al. 2010 §4.1, "tending to unify their
// parameterization"), and neighbours that cannot agree (running the other way, at another
// phase) never settle. On FlightHelmet at 640×480, after 60 frames of a still view, 12 % of
// the crease sample pairs and 9 % of the silhouette pairs still moved by more than 0.5 px a
// frame (docs/BENCHMARKS.md). So a path is given an identity across frames, as the coherence
// issue proposes: a path whose samples (pixels, arclengths and surface points) are bit for
// bit those of a path of the previous frame, seen by the same camera, did not move, and keeps
// that path's pieces (where it was split, path_split.h) and their parameters. Paths that did
// move are parameterized from the splat as before, beside the kept ones.
//
// Input:  a frame's paths (as the tracker receives them, before loops are rotated or paths
//         split) and the record of the previous frame.
// Output: per path, the record entry it matches (or none); its pieces rebuilt from the
//         record; and the record of this frame, for the next.
#pragma once

#include <cstdint>
#include <vector>

#include "coherence/path_param.h"
#include "coherence/path_split.h"
#include "types/screen_path.h"

namespace lw {

// A piece a path was cut into: samples [first, first + count) of the path as rotated.
struct StillPiece {
    uint32_t first = 0, count = 0;
    PathParam param;
};
// One path of a frame: its key, the sample its loop was rotated to start at (0: none) and
// its pieces, [first_piece, first_piece + pieces) of the record's pieces.
struct StillPath {
    uint64_t key = 0;
    uint32_t rotation = 0, first_piece = 0, pieces = 0;
};
struct StillRecord {
    std::vector<StillPath> paths;  // sorted by key
    std::vector<StillPiece> pieces;
    uint64_t settings = 0;         // the key of the settings and scale they were made with
};

// The paths of a frame that moved, parameterized: their pieces and parameters, where each
// piece came from (its path's index among the moved), and where each moved loop was made to
// start (0: not rotated).
struct MovedPaths {
    std::vector<ScreenPath> pieces;
    std::vector<PathParam> params;
    std::vector<PieceOrigin> origins;
    std::vector<uint32_t> rotations;
};

// One step of the keys' hash: `word` mixed into `h`.
[[nodiscard]] uint64_t still_key_step(uint64_t h, uint64_t word);

// A 64-bit hash of what places a path's samples: type, closed and visible, and per sample
// the bits of its pixel, arclength and surface point.
[[nodiscard]] uint64_t still_path_key(const ScreenPath& path);

// The record's path with `key`, if any (of several, the first).
[[nodiscard]] const StillPath* find_still_path(const StillRecord& record, uint64_t key);

// A closed loop started at sample `start` instead: the samples rotated and their arclengths
// measured from the new start (the closing segment counted).
void rotate_loop(ScreenPath& path, size_t start);

// A frame's paths in their input order, each with its pieces in order (as the tracker's
// pipeline leaves them), into `paths`, and their parameters into `params`: path p is kept
// (`kept[p]`, an entry of `previous`: its pieces cut again from `paths[p]`) or moved (the next
// of `moved`'s paths). Returns this frame's record (its `settings` left to the caller).
[[nodiscard]] StillRecord assemble_still_frame(std::vector<ScreenPath>& paths, const std::vector<uint64_t>& keys,
                                               const std::vector<const StillPath*>& kept,
                                               const StillRecord& previous, MovedPaths& moved,
                                               std::vector<PathParam>& params);

}  // namespace lw
