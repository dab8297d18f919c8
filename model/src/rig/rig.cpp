// What every rig kind shares: whether it is posed, its rest pose, and rebasing it onto the
// posed drawing.
#include <finbook/model/types.h>

#include <algorithm>

namespace finbook::model {

bool Rig::isPosed() const
{
    return std::any_of(pins.begin(), pins.end(), [](const Pin &p) { return p.rest != p.target; }) ||
           cage.rest != cage.posed || skeleton.isPosed();
}

Rig Rig::atRest() const
{
    Rig r = *this;
    for (Pin &p : r.pins)
        p.target = p.rest;
    r.cage.posed = r.cage.rest;
    r.skeleton = r.skeleton.atRest();
    return r;
}

Rig Rig::rebased() const
{
    Rig r = *this;
    for (Pin &p : r.pins)
        p.rest = p.target;
    r.cage.rest = r.cage.posed;
    r.skeleton = r.skeleton.rebased();
    return r;
}

} // namespace finbook::model
