# Checks one room's place in the layering (run by CTest, see core/CMakeLists.txt):
#   cmake -DCXX=c++ -DROOM=lang -DINCLUDES="dir;dir" -DSOURCE_DIR=core -DWORK_DIR=dir -P check_rooms.cmake
# With the include path the build gives rb_ROOM, a header of every room ROOM may use must be
# found and a header of every other room must not. The table is core/README.md's.
set(uses_base "")
set(uses_lang base)
set(uses_screen base)
set(uses_input base)
set(uses_robot base screen)
set(uses_machine base lang screen input robot)
# A header of each room that pulls in only what its room may use.
set(header_base base/source.h)
set(header_lang lang/token.h)
set(header_screen screen/canvas.h)
set(header_input input/input.h)
set(header_robot robot/robot_link.h)
set(header_machine machine/host.h)

set(rooms base lang screen input robot machine)
set(always "")
include(${CMAKE_CURRENT_LIST_DIR}/../cmake/check_rooms_probe.cmake)
