#include "physics/workbook/reference/dzhanibekov.h"

#include <cassert>
#include <string>

namespace rbw::reference {

Vec3 dzhanibekovInertia() { return Vec3(3.0, 5.0, 9.0); }

Vec3 dzhanibekovL0_B() { return Vec3(0.0, 2.0, 0.01); }

AsymmetricTop dzhanibekov()
{
    std::string error;
    const std::optional<AsymmetricTop> top = AsymmetricTop::make(dzhanibekovInertia(), dzhanibekovL0_B(), error);
    assert(top && "the Dzhanibekov case is a valid asymmetric top");
    return *top;
}

} // namespace rbw::reference
