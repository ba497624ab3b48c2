# Wireshark Lua dissectors generated from the field tables.
#
# Included from tools/CMakeLists.txt: the generator library (also linked into
# the robowire CLI), robowire_dissector_gen, the plugins in
# ${PROJECT_BINARY_DIR}/wireshark/ and their install rule.
# Run with cmake -P (ROBOWIRE_LUA_IN, ROBOWIRE_LUA_OUT): embeds the runtime as a
# C++ raw string literal.
if(CMAKE_SCRIPT_MODE_FILE)
  file(READ ${ROBOWIRE_LUA_IN} lua)
  file(WRITE ${ROBOWIRE_LUA_OUT}.tmp "R\"robowire_lua(${lua})robowire_lua\"\n")
  file(COPY_FILE ${ROBOWIRE_LUA_OUT}.tmp ${ROBOWIRE_LUA_OUT} ONLY_IF_DIFFERENT)
  file(REMOVE ${ROBOWIRE_LUA_OUT}.tmp)
  return()
endif()

set(ROBOWIRE_LUA_RUNTIME ${CMAKE_CURRENT_LIST_DIR}/dissector_runtime.lua)
set(ROBOWIRE_LUA_INC ${CMAKE_CURRENT_BINARY_DIR}/generated/dissector_runtime.inc)
add_custom_command(OUTPUT ${ROBOWIRE_LUA_INC}
  COMMAND ${CMAKE_COMMAND} -DROBOWIRE_LUA_IN=${ROBOWIRE_LUA_RUNTIME} -DROBOWIRE_LUA_OUT=${ROBOWIRE_LUA_INC}
          -P ${CMAKE_CURRENT_LIST_FILE}
  DEPENDS ${ROBOWIRE_LUA_RUNTIME} ${CMAKE_CURRENT_LIST_FILE}
  COMMENT "Embedding the Wireshark dissector runtime")

add_library(robowire_dissector STATIC ${CMAKE_CURRENT_LIST_DIR}/dissector.cpp ${ROBOWIRE_LUA_INC})
target_link_libraries(robowire_dissector PUBLIC robowire_dev)
target_include_directories(robowire_dissector PRIVATE ${CMAKE_CURRENT_BINARY_DIR}/generated)

add_executable(robowire_dissector_gen ${CMAKE_CURRENT_LIST_DIR}/dissector_gen.cpp)
target_link_libraries(robowire_dissector_gen PRIVATE robowire_dissector)

set(ROBOWIRE_WIRESHARK_DIR ${PROJECT_BINARY_DIR}/wireshark)
set(ROBOWIRE_WIRESHARK_PLUGINS ${ROBOWIRE_WIRESHARK_DIR}/robowire_buwizz3.lua ${ROBOWIRE_WIRESHARK_DIR}/robowire_navbot.lua
  ${ROBOWIRE_WIRESHARK_DIR}/robowire_osp.lua)
add_custom_command(OUTPUT ${ROBOWIRE_WIRESHARK_PLUGINS}
  COMMAND ${CMAKE_COMMAND} -E make_directory ${ROBOWIRE_WIRESHARK_DIR}
  COMMAND robowire_dissector_gen all ${ROBOWIRE_WIRESHARK_DIR}
  DEPENDS robowire_dissector_gen
  COMMENT "Generating the Wireshark dissectors")
add_custom_target(robowire_wireshark_plugins ALL DEPENDS ${ROBOWIRE_WIRESHARK_PLUGINS})
if(ROBOWIRE_INSTALL)
  # Installed when they were built (install(FILES ... OPTIONAL) would leave an empty folder).
  install(CODE "
    if(EXISTS \"${ROBOWIRE_WIRESHARK_DIR}/robowire_osp.lua\")
      file(INSTALL DESTINATION \"\${CMAKE_INSTALL_PREFIX}/${CMAKE_INSTALL_DATADIR}/robowire/wireshark\" TYPE FILE
           FILES ${ROBOWIRE_WIRESHARK_PLUGINS})
    else()
      message(STATUS \"Not installing the Wireshark dissectors: not built (cmake --build first)\")
    endif()")
endif()
