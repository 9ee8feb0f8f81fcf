#pragma once
// How a convex polygon of more than four corners (a face cut along contacts, an n-gon from glTF) is
// split into the convex pieces both the mesher (MeshPlan) and the hierarchical element tree
// (ElementTree) start from: quads (0, i, i+1, i+2) fanned from the first corner, then one closing
// triangle. The two must split alike: a patch is read through the one root element holding its
// centroid (ElementTree::locate), so a patch lying across two roots would read only one of them.
#include <cstddef>

namespace radiant::detail {

/// Calls piece(first, count) for each piece of a convex polygon of n corners: the piece's corners are
/// corner 0, then first, first + 1, ..., first + count - 2 (count is 3 or 4). Fewer than 3 corners
/// give no piece.
template <class PieceFunction>
void forEachFanPiece(std::size_t n, PieceFunction&& piece) {
    if (n < 3) return;
    std::size_t i = 1;
    for (; n - i >= 3; i += 2) piece(i, std::size_t{4});
    if (n - i == 2) piece(i, std::size_t{3});
}

} // namespace radiant::detail
