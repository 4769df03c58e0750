// Help → User guide and Help → About.
//
// The user guide is docs/user-guide.md, found by userGuidePath() (app/core/source_root.h:
// the installed copy, else the source tree), shown rendered (Markdown, with its
// screenshots) in a window of its own (objectName "userGuideWindow", its browser
// "userGuideBrowser"). Without a guide the window says where it looked.
// About (objectName "aboutDialog") names the program, its version, the Qt it runs on
// and was built with, and the licence line.
#pragma once

#include <QString>

class QWidget;

namespace rbw {

// Opens the guide's window (non-modal, deleted on close); a second call raises it.
void showUserGuide(QWidget* parent);

// The About text (rich text): version, Qt versions, licence.
QString aboutText();
// Opens About (non-modal, deleted on close).
void showAbout(QWidget* parent);

} // namespace rbw
