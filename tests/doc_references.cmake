# Every docs/*.md file that a source comment, a CMake file or a Markdown file names must exist
# in the repository (cmake -DSOURCE_DIR=... -P doc_references.cmake).
file(GLOB_RECURSE sources LIST_DIRECTORIES false
  ${SOURCE_DIR}/common/*.hpp ${SOURCE_DIR}/common/*.cpp
  ${SOURCE_DIR}/materials/*.hpp ${SOURCE_DIR}/materials/*.cpp ${SOURCE_DIR}/materials/*.h
  ${SOURCE_DIR}/driver/*.hpp ${SOURCE_DIR}/driver/*.cpp ${SOURCE_DIR}/driver/*.c
  ${SOURCE_DIR}/calibration/*.hpp ${SOURCE_DIR}/calibration/*.cpp
  ${SOURCE_DIR}/mpm_adapter/*.hpp ${SOURCE_DIR}/mpm_adapter/*.cpp
  ${SOURCE_DIR}/tests/*.hpp ${SOURCE_DIR}/tests/*.cpp ${SOURCE_DIR}/tests/*.c
  ${SOURCE_DIR}/bench/*.hpp ${SOURCE_DIR}/bench/*.cpp
  ${SOURCE_DIR}/*CMakeLists.txt ${SOURCE_DIR}/*.md)
list(FILTER sources EXCLUDE REGEX "^${SOURCE_DIR}/(build[^/]*|results)/")
set(missing "")
set(count 0)
foreach(f ${sources})
  file(STRINGS ${f} lines REGEX "docs/[A-Za-z0-9_.-]+\\.md")
  foreach(line ${lines})
    string(REGEX MATCHALL "docs/[A-Za-z0-9_.-]+\\.md" refs "${line}")
    foreach(ref ${refs})
      math(EXPR count "${count} + 1")
      if(NOT EXISTS ${SOURCE_DIR}/${ref})
        file(RELATIVE_PATH rel ${SOURCE_DIR} ${f})
        list(APPEND missing "${rel}: ${ref}")
      endif()
    endforeach()
  endforeach()
endforeach()
if(missing)
  list(JOIN missing "\n  " text)
  message(FATAL_ERROR "references to documents that do not exist:\n  ${text}")
endif()
message(STATUS "${count} references to docs/*.md, all present")
