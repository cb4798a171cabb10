// engine/ribbon/problem.h — the dynamic program's input: where each piece samples the exemplar.
//
// Input:  an `Exemplar` E (W × H), a `Ribbon` (pieces, b, s) and optionally a `ForbiddenMask`
//         of the canvas (the avoidance map, §3.1).
// Output: `DpProblem`: for every DP row (every piece; a closed curve adds the terminal piece,
//         a copy of piece 0, §1.5) the texel offsets, relative to a position u, that the
//         kernels of §2 read. Offsets depend only on the piece's shape, never on u (a piece
//         is a similarity copy placed at an integer u, ribbon.h), so they are computed once
//         here and both the C++ reference and the GPU kernels only add u and fetch: integer
//         work that gives bit-identical valid sets and edge colours on both.
//
// Positions (§1.4): u = (x, y), x ∈ [0, W), y ∈ [−C, H): "the top left corner of a piece may
// be located up to C pixels above the exemplar"; U = W·(H + C); index = (y + C)·W + x.
//
// A position is valid for a piece (§1.3, §2 findValidPositions) when
//  1. the piece slices the pattern completely: its top edge (the line through the first
//     samples of its left and right edges) passes above the pattern and its bottom edge
//     below it, the pattern being the band of rows from E's first to its last opaque row.
//     The paper tests that the edges meet no opaque texel; taken literally, that admits a
//     piece holding only a chain link's upper arc (its bottom edge running through the
//     link's eye) or only the thin bar between two links, placed anywhere in the ribbon's
//     height — and the DP prefers those, since fewer opaque pixels mismatch along curved
//     seams: it draws a wandering strand instead of the chain. Requiring the whole band
//     keeps what the paper's inset shows (the valid piece holds the pattern's full height)
//     and leaves the pattern the freedom to diverge from the curve by the ribbon's slack,
//     C − band height;
//  2. it is not empty: some texel inside it is opaque;
//  3. it does not put an opaque texel on a forbidden canvas pixel (§3.1);
//  4. it stays inside E horizontally (our addition: a piece reaching past the exemplar's side
//     would copy a pattern cut by the image border, a cut the edge costs cannot see).
//
// Some pieces have no such position: one lying in an overlap (a curve crossing itself)
// cannot both carry ink and keep it off the forbidden pixels, and where a bend is too tight
// the tilted edges sweep across the pattern. Rather than fail on such curves, that row is
// searched again under looser rules (`ValidityRule`, each only when the stricter found
// nothing, so that the DP never trades ink for a free gap where ink was possible):
//  Empty — a piece touching a forbidden region may be empty, placed wholly above E
//          (u = (−min_dx, −C)) where every texel is transparent black: one position stands
//          for all empty placements, which would all cost the same (the paper's Fig. 3
//          shows such gaps at overlaps);
//  Edges — the paper's literal test for 1 (the edges meet no opaque texel), with 2;
//  Any   — 3 and 4 only: the piece may cut the pattern.
// The rows that needed one are reported (DpTables::rules), so that the user can shorten δ.
#pragma once

#include <cstdint>
#include <optional>
#include <vector>

#include <glm/glm.hpp>

#include "ribbon/avoidance.h"
#include "ribbon/exemplar.h"
#include "ribbon/ribbon.h"

namespace lw {

struct PieceProbes {
    std::vector<glm::ivec2> left;       // C texel offsets of the left-edge samples L̄ (tilted where
                                        // the curve turns over the piece, ribbon.h; else a column)
    std::vector<glm::ivec2> right;      // C texel offsets of the right-edge samples R̄ (tilted edge)
    std::vector<glm::ivec2> top;        // texels along the top edge: must lie above the band
    std::vector<glm::ivec2> bottom;     // texels along the bottom edge: must lie below the band
    std::vector<glm::ivec2> interior;   // texels inside the piece: one must be opaque
    std::vector<glm::ivec2> forbidden;  // texels drawn on forbidden canvas pixels: must be transparent
    int min_dx = 0, max_dx = 0;         // horizontal extent of every texel above
    bool touches_forbidden = false;     // the piece covers a forbidden pixel (ValidityRule::Empty applies)
};

struct DpProblem {
    const Exemplar* exemplar = nullptr;
    int samples = 0;             // C = ⌈s⌉
    glm::ivec2 band{0, -1};      // first and last row of E holding an opaque texel
    std::vector<PieceProbes> rows;
    bool closed = false;         // rows.back() is the terminal piece and must equal rows[0]'s position

    uint32_t position_count() const {  // U
        return uint32_t(exemplar->width) * uint32_t(exemplar->height + samples);
    }
    glm::ivec2 position(uint32_t index) const {
        return {int(index % uint32_t(exemplar->width)), int(index / uint32_t(exemplar->width)) - samples};
    }
    uint32_t index(glm::ivec2 u) const { return uint32_t(u.y + samples) * uint32_t(exemplar->width) + uint32_t(u.x); }
};

[[nodiscard]] DpProblem build_problem(const Exemplar& exemplar, const Ribbon& ribbon,
                                      const ForbiddenMask* forbidden = nullptr);

// First and last row of E holding an opaque texel (the pattern's band).
[[nodiscard]] glm::ivec2 pattern_band(const Exemplar& exemplar);
// The default s: the band's height, 2 rows for the edges, and 30 % of it (at least 2 rows) as
// the pattern's freedom to diverge from the curve.
[[nodiscard]] float default_ribbon_scale(const Exemplar& exemplar);
// A scale s at which no piece can hold the whole band, even along a straight curve: its first
// and last edge samples, at (k + 0.5)/C of s with C = ⌈s⌉ (ribbon.h), lie less than the band's
// height + 1 rows apart (s = 33 for a 32-row band; 33.5 and 34 hold it). Then every piece
// needs a looser rule and may cut the pattern, whatever the curve does: the reason the command
// line and Python give for cut pieces, with these figures.
struct ScaleShortfall {
    int band_rows = 0;         // the pattern's height
    int least_scale = 0;       // the least whole s that holds it: a row above and below
    float default_scale = 0;   // default_ribbon_scale
};
[[nodiscard]] std::optional<ScaleShortfall> scale_shortfall(const Exemplar& exemplar, float scale);

// The probes of one piece (exposed for tests).
[[nodiscard]] PieceProbes piece_probes(const Ribbon& ribbon, size_t piece, const ForbiddenMask* forbidden);

// The validity tests in order of preference (see above); each row uses the first that
// leaves a valid position.
enum class ValidityRule : int { Band = 0, Empty = 1, Edges = 2, Any = 3 };

// Validity of position u for `row`, the test of findValidPositions.
[[nodiscard]] bool position_valid(const DpProblem& problem, size_t row, glm::ivec2 u,
                                  ValidityRule rule = ValidityRule::Band);

}  // namespace lw
