# Read by cpack for each generator (CPACK_PROJECT_CONFIG_FILE): the archive is relocatable and
# unpacks into a folder of its own; the Debian package installs into /usr.
if(CPACK_GENERATOR STREQUAL "TGZ")
  set(CPACK_PACKAGING_INSTALL_PREFIX "")
  set(CPACK_INCLUDE_TOPLEVEL_DIRECTORY ON)
endif()
