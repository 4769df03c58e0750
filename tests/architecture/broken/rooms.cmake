# The rooms of the broken tree (the negative control of check_rooms.cmake).
rbw_room(physics/engine QT_FREE MAX_LINES 450)
rbw_room(app/scene MAY_INCLUDE physics/engine)
rbw_room(app/gui/shell MAY_INCLUDE physics app)
