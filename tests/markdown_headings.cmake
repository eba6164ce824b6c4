# markdown_headings(DOC OUT): the headings of the Markdown file DOC, lower case, stripped, without
# the marks no reference keeps (`, *, square brackets and ';', on which CMake lists split except
# inside brackets). Shared by doc_references.cmake (cited sections) and markdown_links.cmake
# (anchors).
function(markdown_headings doc out)
  file(READ ${doc} text)
  string(REGEX REPLACE "[][;`*]" "" text "${text}")
  string(REGEX MATCHALL "(^|\n)#+ [^\n]*" found "${text}")
  set(result "")
  foreach(h IN LISTS found)
    string(REGEX REPLACE "^\n?#+ +" "" h "${h}")
    string(STRIP "${h}" h)
    string(TOLOWER "${h}" h)
    list(APPEND result "${h}")
  endforeach()
  set(${out} "${result}" PARENT_SCOPE)
endfunction()
