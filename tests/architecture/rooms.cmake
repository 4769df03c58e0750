# The rooms of the source tree and the borders between them (docs/architecture.md,
# "Rooms and borders"). check_rooms.cmake reads this table; change a border here, in
# the room's README.md and in docs/architecture.md together.
#
# rbw_room(FOLDER MAY_INCLUDE PREFIX... [QT_FREE] [MAX_LINES N])
#   FOLDER       a folder of the repository; its files (recursively, but not those of a
#                deeper room) belong to the room
#   MAY_INCLUDE  the repository paths its files may #include "..." (a prefix matches a
#                folder and everything under it); its own folder is always allowed
#   QT_FREE      no #include <Q...> at all
#   MAX_LINES    no .h or .cpp file longer than N lines (default: .cpp files at most 600)
# A file's include is checked when it names a file of the repository (path from the
# root); includes of the room's own generated files (moc) and system headers are not.

rbw_room(physics/engine            QT_FREE MAX_LINES 450)
rbw_room(physics/workbook          MAY_INCLUDE physics/engine QT_FREE MAX_LINES 450)

rbw_room(app/output                MAY_INCLUDE physics)
rbw_room(app/scene                 MAY_INCLUDE physics/engine app/output)
rbw_room(app/core                  MAY_INCLUDE physics/engine app/scene)
rbw_room(app/exercise              MAY_INCLUDE physics app/core app/output app/scene)
rbw_room(app/derivation            MAY_INCLUDE physics app/core app/output)
rbw_room(app/simulator             MAY_INCLUDE physics app/core)
rbw_room(app/cli                   MAY_INCLUDE physics app/core app/output app/scene app/exercise app/derivation
                                               app/simulator)

rbw_room(app/gui/style)
rbw_room(app/gui/panels/view       MAY_INCLUDE physics/engine app/core app/output app/gui/style)
rbw_room(app/gui/panels/derivation MAY_INCLUDE physics app/core app/output app/derivation)
rbw_room(app/gui/panels/quantities MAY_INCLUDE physics/engine app/core app/output app/derivation
                                               app/gui/style app/gui/panels/derivation)
rbw_room(app/gui/panels/plots      MAY_INCLUDE physics app/core app/output app/gui/style)
rbw_room(app/gui/panels/accuracy   MAY_INCLUDE physics app/core app/output app/exercise)
rbw_room(app/gui/panels/check      MAY_INCLUDE physics app/core app/output app/exercise)
rbw_room(app/gui/panels/editor     MAY_INCLUDE physics/engine app/scene)
rbw_room(app/gui/panels/simulator  MAY_INCLUDE physics app/core app/simulator)
rbw_room(app/gui/shell             MAY_INCLUDE physics app)

# The student's side of the simulator protocol: it stands in for a student's own code,
# so it uses nothing of the workbook's.
rbw_room(examples/simulator)
