# The temporary directory every test of tests/ runs in (TMPDIR; see tests/CMakeLists.txt):
#   cmake -DMODE=prepare -DDIRECTORY=D -P test_tmpdir.cmake       D exists and is empty
#   cmake -DMODE=left_nothing -DDIRECTORY=D -P test_tmpdir.cmake  fails, listing D's contents,
#                                                                 unless D is empty
# What a failed check found stays in D for inspection until the next prepare.
if(NOT DEFINED DIRECTORY OR DIRECTORY STREQUAL "")
  message(FATAL_ERROR "test_tmpdir.cmake: give -DDIRECTORY=")
endif()
if(MODE STREQUAL "prepare")
  file(REMOVE_RECURSE "${DIRECTORY}")
  file(MAKE_DIRECTORY "${DIRECTORY}")
elseif(MODE STREQUAL "left_nothing")
  file(GLOB_RECURSE left RELATIVE "${DIRECTORY}" LIST_DIRECTORIES true "${DIRECTORY}/*")
  file(GLOB hidden RELATIVE "${DIRECTORY}" LIST_DIRECTORIES true "${DIRECTORY}/.*")
  list(APPEND left ${hidden})
  if(left)
    list(SORT left)
    list(JOIN left "\n  " names)
    message(FATAL_ERROR "tests left these in their temporary directory ${DIRECTORY}:\n  ${names}")
  endif()
  message(STATUS "nothing left in ${DIRECTORY}")
else()
  message(FATAL_ERROR "test_tmpdir.cmake: MODE must be prepare or left_nothing, not '${MODE}'")
endif()
