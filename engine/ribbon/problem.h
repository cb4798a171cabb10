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
//  1. the piece slices the pattern completely: every texel along its top and bottom edges
//     (the lines through the first and last edge samples) is transparent;
//  2. it is not empty: some texel inside it is opaque — waived for a piece that touches a
//     forbidden region, which may have to stay empty there (our choice, see below);
//  3. it does not put an opaque texel on a forbidden canvas pixel (§3.1);
//  4. it stays inside E horizontally (our addition: a piece reaching past the exemplar's side
//     would copy a pattern cut by the image border, a cut the edge costs cannot see).
// Waiving 2 lets a piece that lies wholly in an overlap (a curve crossing itself) take an
// empty position instead of leaving the row with no valid position at all.
#pragma once

#include <cstdint>
#include <vector>

#include <glm/glm.hpp>

#include "ribbon/avoidance.h"
#include "ribbon/exemplar.h"
#include "ribbon/ribbon.h"

namespace lw {

struct PieceProbes {
    std::vector<glm::ivec2> right;      // C texel offsets of the right-edge samples R̄ (tilted edge)
    std::vector<glm::ivec2> boundary;   // texels along the top and bottom edges: must be transparent
    std::vector<glm::ivec2> interior;   // texels inside the piece: one must be opaque (unless !require_ink)
    std::vector<glm::ivec2> forbidden;  // texels drawn on forbidden canvas pixels: must be transparent
    int min_dx = 0, max_dx = 0;         // horizontal extent of every texel above
    bool require_ink = true;            // false when the piece covers a forbidden pixel
};

struct DpProblem {
    const Exemplar* exemplar = nullptr;
    int samples = 0;             // C = ⌈s⌉
    std::vector<int> left_dy;    // C row offsets of the left-edge samples L̄ (column x of E)
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

// The probes of one piece (exposed for tests).
[[nodiscard]] PieceProbes piece_probes(const Ribbon& ribbon, size_t piece, const ForbiddenMask* forbidden);

// Validity of position u for `row`, the test of findValidPositions.
[[nodiscard]] bool position_valid(const DpProblem& problem, size_t row, glm::ivec2 u);

}  // namespace lw
