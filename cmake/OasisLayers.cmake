# The layer check over the whole tree (cmake/check_layers.py): every file of compiler/, hw/,
# common/, tools/ and runtime/ may include only headers of the targets its own target reaches
# through its links, and a target links nothing whose headers it never includes. The links are
# the rules: nothing is declared twice. At the end of configuring, oasis_check_layers() writes
# every target's sources and links to a table in the build folder; a build step checks the
# tree against it before any of our targets compiles, and ctest runs the same check (layers.*).
#
# Two target properties say what the links cannot:
#   OASIS_HEADER_FOLDERS   the folders a header-only (INTERFACE) library holds
#   OASIS_HEADER_ONLY_USES folders whose headers a target includes on purpose without linking
#                          their library (a deliberate crossing, written where the target is
#                          defined, with the reason beside it)

set(OASIS_CHECK_LAYERS "${CMAKE_CURRENT_LIST_DIR}/check_layers.py")

# Every target defined in DIR and the folders below it.
function(_oasis_targets_below dir out)
  get_property(found DIRECTORY "${dir}" PROPERTY BUILDSYSTEM_TARGETS)
  get_property(subdirectories DIRECTORY "${dir}" PROPERTY SUBDIRECTORIES)
  foreach(subdirectory IN LISTS subdirectories)
    _oasis_targets_below("${subdirectory}" below)
    list(APPEND found ${below})
  endforeach()
  set(${out} ${found} PARENT_SCOPE)
endfunction()

# One line per target: name, type, source folder, sources, links, interface links, header
# folders, header-only uses; fields separated by tabs, list items by '|'. Imported targets our
# targets link are written too (their interface links only), so that reach is followed through
# them.
function(_oasis_link_table_line target out)
  set(fields "${target}")
  foreach(property TYPE SOURCE_DIR SOURCES LINK_LIBRARIES INTERFACE_LINK_LIBRARIES
                   OASIS_HEADER_FOLDERS OASIS_HEADER_ONLY_USES)
    get_target_property(value ${target} ${property})
    if(NOT value)
      set(value "")
    endif()
    string(REPLACE ";" "|" value "${value}")
    string(REPLACE "\t" " " value "${value}")
    list(APPEND fields "${value}")
  endforeach()
  string(REPLACE ";" "\t" line "${fields}")
  set(${out} "${line}" PARENT_SCOPE)
endfunction()

function(_oasis_write_link_table path)
  _oasis_targets_below("${PROJECT_SOURCE_DIR}" pending)
  set(written "")
  set(table "")
  while(pending)
    list(POP_FRONT pending target)
    if(target IN_LIST written OR NOT TARGET ${target})
      continue()
    endif()
    get_target_property(aliased ${target} ALIASED_TARGET)
    if(aliased)
      list(APPEND pending ${aliased})
      continue()
    endif()
    list(APPEND written ${target})
    _oasis_link_table_line(${target} line)
    string(APPEND table "${line}\n")
    get_target_property(links ${target} INTERFACE_LINK_LIBRARIES)
    get_target_property(type ${target} TYPE)
    if(NOT type STREQUAL "INTERFACE_LIBRARY")
      get_target_property(own ${target} LINK_LIBRARIES)
      list(APPEND links ${own})
    endif()
    foreach(link IN LISTS links)
      string(REGEX REPLACE "^\\$<LINK_ONLY:(.*)>$" "\\1" link "${link}")
      if(TARGET "${link}")
        list(APPEND pending "${link}")
      endif()
    endforeach()
  endwhile()
  file(WRITE "${path}.new" "${table}")
  file(COPY_FILE "${path}.new" "${path}" ONLY_IF_DIFFERENT)
  file(REMOVE "${path}.new")
endfunction()

# Writes the table and adds the build step: every target of ours waits for the check.
function(oasis_check_layers)
  set(table "${PROJECT_BINARY_DIR}/layers/link_table.tsv")
  _oasis_write_link_table("${table}")
  set(checked_folders compiler hw common tools runtime)
  set(files "")
  foreach(folder IN LISTS checked_folders)
    file(GLOB_RECURSE found CONFIGURE_DEPENDS "${PROJECT_SOURCE_DIR}/${folder}/*.[ch]pp")
    list(APPEND files ${found})
  endforeach()
  set(stamp "${PROJECT_BINARY_DIR}/layers/tree.checked")
  add_custom_command(
    OUTPUT "${stamp}"
    COMMAND Python3::Interpreter "${OASIS_CHECK_LAYERS}" --table "${table}"
            --root "${PROJECT_SOURCE_DIR}" --stamp "${stamp}"
    DEPENDS ${files} "${OASIS_CHECK_LAYERS}" "${table}"
    COMMENT "Checking every #include against the links of its target (cmake/check_layers.py)")
  add_custom_target(oasis_layer_check DEPENDS "${stamp}")
  _oasis_targets_below("${PROJECT_SOURCE_DIR}" targets)
  foreach(target IN LISTS targets)
    get_target_property(type ${target} TYPE)
    get_target_property(folder ${target} SOURCE_DIR)
    if(type MATCHES "^(STATIC_LIBRARY|SHARED_LIBRARY|OBJECT_LIBRARY|EXECUTABLE)$"
       AND folder MATCHES "^${PROJECT_SOURCE_DIR}/(compiler|hw|common|tools)(/|$)")
      add_dependencies(${target} oasis_layer_check)
    endif()
  endforeach()
endfunction()
