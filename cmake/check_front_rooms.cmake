# Checks one front-end room's place in the house (run by CTest, see the top-level CMakeLists.txt):
#   cmake -DCXX=c++ -DROOM=tui -DINCLUDES="dir;dir" -DWORK_DIR=dir -P check_front_rooms.cmake
# With the include path the build gives rb_ROOM, a header of every room ROOM may use must be
# found and a header of every other front room must not. core/ is under every room (its own
# rooms are checked by core/check_rooms.cmake); cmd/ is wiring on top of all of them.
# The table is docs/architecture.md's ("The rooms of the front ends").
set(uses_render "")
set(uses_drivers "")
set(uses_diagnostics "")
set(uses_lsp "")
set(uses_record render)
set(uses_grade record render)
set(uses_run drivers diagnostics)
set(uses_tui render run drivers diagnostics)
set(uses_web render)
# A header of each room that is found only on that room's include path.
set(header_render png_writer.h)
set(header_drivers serial_link.h)
set(header_diagnostics diagnostic_output.h)
set(header_lsp lsp/server.h)
set(header_record trace_writer.h)
set(header_grade grader.h)
set(header_run program_run.h)
set(header_tui tui_host.h)
set(header_web web_host.h)
set(header_cmd run_command.h)
set(rooms render drivers diagnostics record lsp grade run tui web cmd)

set(always core)
include(${CMAKE_CURRENT_LIST_DIR}/check_rooms_probe.cmake)
