// A slice mapped across a symmetry of the pair, named as the slice computed at its own
// orientation would be (src/slice/slice_image.cpp, docs/symmetry.md).
#pragma once

#include <optional>

#include "contacts/contact_features.hpp"
#include "cslice/slice.hpp"
#include "cslice/symmetry.hpp"

namespace cslice {

// mapped_slice, with the contact segments `contacts` makes at theta in place of the mapped
// ones (their ids and order: those of the slice computed there), every id translated by label,
// and every piece along coincident contact segments named by the lowest of their new ids, as
// the computed slice names it. Nothing when a contact segment the source's structure uses, or
// one longer than the geometric epsilon, has no counterpart at theta: compute that slice.
std::optional<Slice> mapped_slice_as_computed(const Slice& source, const PairSymmetry& symmetry,
                                              double theta, ContactMaker& contacts);

}  // namespace cslice
