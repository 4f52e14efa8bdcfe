# The browser host's room (web/host/): its include path, which the wasm build (web/CMakeLists.txt)
# compiles with and the native build's rooms check (cmake/check_front_rooms.cmake, "rooms: web")
# tests: core/, render/ (the arena and the robot drawn as rb render draws them) and the host
# itself; none of the other front ends' rooms (run/, tui/, cmd/, ...), whose files, terminals
# and serial ports a page has not got. RB_ROOT is the source tree's top.
set(RB_WEB_HOST_INCLUDES ${RB_ROOT}/core ${RB_ROOT}/render ${RB_ROOT}/web/host)
