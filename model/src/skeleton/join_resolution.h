// resolveJoins with a bound on its work, for the reader: a file cannot make opening cost more
// than in proportion to its size (private to the model).
#pragma once

#include <finbook/model/types.h>

#include <cstdint>
#include <vector>

namespace finbook::model::join_detail {

// resolveJoins(frame) that looks at no more than `budget` bones and tree nodes in all (the
// budget shrinks by what it used). False when it ran out: the frame's anchors are then not
// all resolved and the frame must not be used as it is. `changed` (optional) gets what
// resolveJoins returns.
bool resolveJoinsWithin(Frame &frame, std::int64_t &budget, std::vector<Id> *changed = nullptr);

// The work resolveJoins needs at most on the frames of a well-made file: what the reader
// allows (a file whose joins need more is refused as too costly to open): 2^20 + 64 units
// per object and per joint, about a second at worst.
std::int64_t joinWorkAllowance(const std::vector<Frame> &frames);

} // namespace finbook::model::join_detail
