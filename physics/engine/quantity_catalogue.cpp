#include "physics/engine/quantity_catalogue.h"

namespace rbw {

const QuantityInfo* findQuantity(std::string_view id)
{
    for (const QuantityInfo& q : kQuantityCatalogue) {
        if (id == q.id) return &q;
    }
    return nullptr;
}

} // namespace rbw
