#include "app/gui/panels/quantities/quantities_session_panel.h"

#include "app/core/session.h"
#include "app/gui/panels/quantities/trace_model.h"

namespace rbw {

void QuantitiesSessionPanel::sceneLoaded(const World& world)
{
    model_->setStart(world);   // the state at t = 0 before the first step
}

void QuantitiesSessionPanel::refresh()
{
    const World* world = session_->world();
    if (world == nullptr) return;
    // A new step (or step back, or reset): the table shows its trace.
    if (const StepTrace* trace = session_->currentTrace()) model_->setTrace(*trace, world->scene());
    else model_->setStart(*world);
}

} // namespace rbw
