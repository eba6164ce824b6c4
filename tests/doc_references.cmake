# Every docs/*.md file that a source comment, a CMake file, a study script, a data description or
# a Markdown file names must exist in the repository, and where the reference names a section
# (the document's path, a comma and the section in double or single quotes), the document must
# have a heading that starts with it
# (cmake -DSOURCE_DIR=... -P doc_references.cmake).
file(GLOB_RECURSE sources LIST_DIRECTORIES false
  ${SOURCE_DIR}/common/*.hpp ${SOURCE_DIR}/common/*.cpp
  ${SOURCE_DIR}/materials/*.hpp ${SOURCE_DIR}/materials/*.cpp ${SOURCE_DIR}/materials/*.h
  ${SOURCE_DIR}/driver/*.hpp ${SOURCE_DIR}/driver/*.cpp ${SOURCE_DIR}/driver/*.c
  ${SOURCE_DIR}/calibration/*.hpp ${SOURCE_DIR}/calibration/*.cpp
  ${SOURCE_DIR}/mpm_adapter/*.hpp ${SOURCE_DIR}/mpm_adapter/*.cpp
  ${SOURCE_DIR}/tests/*.hpp ${SOURCE_DIR}/tests/*.cpp ${SOURCE_DIR}/tests/*.c
  ${SOURCE_DIR}/bench/*.hpp ${SOURCE_DIR}/bench/*.cpp ${SOURCE_DIR}/bench/*.py ${SOURCE_DIR}/studies/*.py
  ${SOURCE_DIR}/data/*.json
  ${SOURCE_DIR}/*CMakeLists.txt ${SOURCE_DIR}/*.md)
list(FILTER sources EXCLUDE REGEX "^${SOURCE_DIR}/(build[^/]*|results|\\.git)/")
list(FILTER sources EXCLUDE REGEX "/tests/fuzz/corpus/")

include(${CMAKE_CURRENT_LIST_DIR}/markdown_headings.cmake)

set(missing "")
set(count 0)
set(sections 0)
foreach(f ${sources})
  file(RELATIVE_PATH rel ${SOURCE_DIR} ${f})
  file(READ ${f} text)
  # One line: a reference may wrap across lines of a comment (// or #) or of a paragraph.
  string(REGEX REPLACE "[][;`*]" "" text "${text}")
  string(REGEX REPLACE "\n[ \t]*(//|#)?[ \t]*" " " text "${text}")
  string(REPLACE "\\\"" "\"" text "${text}")
  string(REGEX MATCHALL "docs/[A-Za-z0-9_.-]+\\.md" refs "${text}")
  foreach(ref ${refs})
    math(EXPR count "${count} + 1")
    if(NOT EXISTS ${SOURCE_DIR}/${ref})
      list(APPEND missing "${rel}: ${ref}")
    endif()
  endforeach()
  string(REGEX MATCHALL "docs/[A-Za-z0-9_.-]+\\.md, +[\"'][^\"']+[\"']" cited "${text}")
  foreach(c ${cited})
    string(REGEX REPLACE "^(docs/[A-Za-z0-9_.-]+\\.md), +[\"']([^\"']+)[\"']$" "\\1" doc "${c}")
    string(REGEX REPLACE "^(docs/[A-Za-z0-9_.-]+\\.md), +[\"']([^\"']+)[\"']$" "\\2" section "${c}")
    if(NOT EXISTS ${SOURCE_DIR}/${doc})
      continue()
    endif()
    math(EXPR sections "${sections} + 1")
    string(TOLOWER "${section}" section)
    string(STRIP "${section}" section)
    markdown_headings(${SOURCE_DIR}/${doc} headings)
    set(found FALSE)
    foreach(h IN LISTS headings)
      string(FIND "${h}" "${section}" at)
      if(at EQUAL 0)
        set(found TRUE)
        break()
      endif()
    endforeach()
    if(NOT found)
      list(APPEND missing "${rel}: ${doc}, \"${section}\" (no such heading)")
    endif()
  endforeach()
endforeach()
if(missing)
  list(JOIN missing "\n  " text)
  message(FATAL_ERROR "references to documents or sections that do not exist:\n  ${text}")
endif()
message(STATUS "${count} references to docs/*.md, all present; ${sections} name a section, all found")
