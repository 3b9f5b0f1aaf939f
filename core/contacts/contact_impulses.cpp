#include "core/contacts/contact_impulses.h"

#include <vector>

namespace core {

void renumberContactImpulses(std::vector<ContactImpulse> &impulses, const std::vector<int> &remap)
{
    const auto renumbered = [&](int p) {
        return p >= 0 && std::size_t(p) < remap.size() ? remap[std::size_t(p)] : -1;
    };
    std::vector<ContactImpulse> kept;
    for (ContactImpulse impulse : impulses) {
        // (a removed partner's -1 must not be read as plane 0)
        const int i = renumbered(impulse.i);
        const int j = impulse.withPlane() ? impulse.j : renumbered(impulse.j);
        if (i < 0 || (!impulse.withPlane() && j < 0))
            continue;
        impulse.i = i;
        impulse.j = j;
        kept.push_back(impulse);
    }
    impulses = std::move(kept);
}

void removePlaneFromContactImpulses(std::vector<ContactImpulse> &impulses, int removed)
{
    std::erase_if(impulses, [removed](const ContactImpulse &c) { return c.withPlane() && c.plane() == removed; });
    for (ContactImpulse &c : impulses)
        if (c.withPlane() && c.plane() > removed)
            c.j = -1 - (c.plane() - 1);
}

}  // namespace core
