#include "app/gui/panels/check/check_session_panel.h"

#include "app/core/session.h"
#include "app/gui/panels/check/check_panel.h"

namespace rbw {

void CheckSessionPanel::refresh()
{
    if (!session_->isLoaded()) return;
    panel_->setStep(lessonId_(), session_->worldBeforeCurrentStep(), session_->currentTrace(), session_->world()->scene());
}

} // namespace rbw
