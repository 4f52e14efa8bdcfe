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
# A header of each room that is found only on that room's include path.
set(header_render png_writer.h)
set(header_drivers serial_link.h)
set(header_diagnostics diagnostic_output.h)
set(header_lsp lsp/server.h)
set(header_record trace_writer.h)
set(header_grade grader.h)
set(header_run program_run.h)
set(header_tui tui_host.h)
set(header_cmd run_command.h)
set(rooms render drivers diagnostics record lsp grade run tui cmd)

if(NOT DEFINED uses_${ROOM})
  message(FATAL_ERROR "unknown room '${ROOM}'")
endif()
set(flags)
foreach(dir ${INCLUDES})
  list(APPEND flags -I${dir})
endforeach()
file(MAKE_DIRECTORY ${WORK_DIR})

set(failures)
foreach(other ${rooms})
  if(other STREQUAL ROOM)
    continue()
  endif()
  list(FIND uses_${ROOM} ${other} allowed)
  set(probe ${WORK_DIR}/${ROOM}_uses_${other}.cpp)
  file(WRITE ${probe} "#include \"${header_${other}}\"\n")
  execute_process(COMMAND ${CXX} -std=c++20 -E ${flags} ${probe} -o ${WORK_DIR}/${ROOM}_uses_${other}.i
                  RESULT_VARIABLE status ERROR_VARIABLE errors)
  if(allowed GREATER -1 AND NOT status EQUAL 0)
    list(APPEND failures "${ROOM}/ may use ${other}/ but cannot include ${header_${other}}:\n${errors}")
  elseif(allowed EQUAL -1 AND status EQUAL 0)
    list(APPEND failures "${ROOM}/ may not use ${other}/, yet ${header_${other}} is on its include path")
  elseif(allowed EQUAL -1 AND NOT errors MATCHES "No such file")
    list(APPEND failures "${ROOM}/ including ${header_${other}} failed for another reason than a missing file:\n${errors}")
  endif()
endforeach()

if(failures)
  string(JOIN "\n" text ${failures})
  message(FATAL_ERROR "${text}")
endif()
message(STATUS "${ROOM}/ sees exactly: ${ROOM} core ${uses_${ROOM}}")
