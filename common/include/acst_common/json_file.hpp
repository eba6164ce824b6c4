#pragma once
// The one reader of a JSON input file (a scene, a fit description, a sweep, a material file the
// input names): the file read with read_input_file's checks, the text parsed with
// parse_document's, and every failure worded one way.
#include <nlohmann/json.hpp>
#include <string>

namespace acst::common::fields {

// The document in the file `path`, or an InputError "<what> '<path>': <reason>":
//   the scene file 'a.json': cannot open: No such file or directory
//   the scene file '/dev/zero': a character device, not a regular file
//   the fit description 'f.json': not valid JSON: parse error at line 3, column 7: syntax error ...
//   the material file 'm.json': not valid JSON: at /parameters/G0: number overflow parsing '1e999'
// `named_at`, the JSON path of the input that names the file (/material/file), goes in front
// ("/material/file: the material file 'm.json': ..."), as every error inside a document starts
// with its path.
nlohmann::json read_json_file(const std::string& path, const std::string& what, const std::string& named_at = "");

// The same for a file's text already read (`path` only names it in the messages).
nlohmann::json parse_json_file_text(const std::string& text, const std::string& path, const std::string& what,
                                    const std::string& named_at = "");

}  // namespace acst::common::fields
