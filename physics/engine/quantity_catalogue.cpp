#include "physics/engine/quantity_catalogue.h"

namespace rbw {

namespace {

// The rows of one trace id are one quantity to a reader: they share its display name.
consteval bool namesAgreeWithinAnId()
{
    constexpr std::size_t n = std::size(kQuantityCatalogue);
    std::array<std::string_view, n> ids{};
    std::array<std::string_view, n> names{};
    for (std::size_t i = 0; i < n; ++i) {
        ids[i] = kQuantityCatalogue[i].id;
        names[i] = kQuantityCatalogue[i].name;
        if (names[i].empty()) return false;
    }
    for (std::size_t i = 0; i < n; ++i) {
        for (std::size_t j = i + 1; j < n; ++j) {
            if (ids[i] == ids[j] && names[i] != names[j]) return false;
        }
    }
    return true;
}
static_assert(namesAgreeWithinAnId(), "every row of a trace id needs the same non-empty display name");

} // namespace

const QuantityInfo* findQuantity(std::string_view id)
{
    for (const QuantityInfo& q : kQuantityCatalogue) {
        if (id == q.id) return &q;
    }
    return nullptr;
}

} // namespace rbw
