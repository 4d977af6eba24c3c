// A case file's text into a JSON document: parsed with its checks (json_parse.hpp), relative
// file names resolved against the file's folder, and the command line's `--set path=value`
// overrides applied before the case is read (build_case).
#include <algorithm>
#include <filesystem>
#include <fstream>
#include <sstream>
#include <string>
#include <vector>

#include "case_model.hpp"
#include "errors.hpp"
#include "json_block.hpp"
#include "json_parse.hpp"

namespace dc {

using namespace case_json;

namespace {

bool all_digits(const std::string& s) {
  return !s.empty() && std::all_of(s.begin(), s.end(), [](char ch) { return ch >= '0' && ch <= '9'; });
}

}  // namespace

nlohmann::json parse_case_text(const std::string& text, const std::string& origin) {
  try {
    return parse_json_checked(text, origin);
  } catch (const json::parse_error& e) {
    std::size_t pos = e.byte == 0 ? 0 : e.byte - 1;  // 0-based index of the offending character
    pos = std::min(pos, text.size());
    std::size_t line = 1, line_start = 0;
    for (std::size_t i = 0; i < pos; ++i)
      if (text[i] == '\n') {
        ++line;
        line_start = i + 1;
      }
    const std::size_t column = pos - line_start + 1;
    std::string reason = e.what();
    const auto at = reason.find(", column ");
    const auto colon = reason.find(": ", at == std::string::npos ? 0 : at);
    if (colon != std::string::npos) reason = reason.substr(colon + 2);
    throw InputError(origin, "malformed JSON at line " + std::to_string(line) + ", column " +
                                 std::to_string(column) + ": " + reason);
  }
}

nlohmann::json read_case_file(const std::string& path) {
  namespace fs = std::filesystem;
  std::error_code ec;
  if (fs::is_directory(path, ec)) throw InputError(path, "cannot open (it is a directory)");
  std::ifstream in(path, std::ios::binary);
  if (!in) throw InputError(path, "cannot open");
  std::ostringstream text;
  text << in.rdbuf();
  json doc = parse_case_text(text.str(), path);
  // Relative file names inside the case are relative to the case file's folder.
  const fs::path folder = fs::path(path).parent_path();
  auto resolve = [&](const char* block, const char* key) {
    if (!doc.is_object() || !doc.contains(block) || !doc[block].is_object()) return;
    json& b = doc[block];
    if (!b.contains(key) || !b[key].is_string()) return;
    const fs::path file(b[key].get<std::string>());
    if (file.is_relative() && !file.empty() && !folder.empty())
      b[key] = (folder / file).lexically_normal().string();
  };
  resolve("profile", "file");
  resolve("fe_body", "mesh");
  return doc;
}

void apply_override(nlohmann::json& document, const std::string& assignment) {
  const auto eq = assignment.find('=');
  if (eq == std::string::npos)
    throw InputError("--set", "expected path=value (e.g. materials.body.E=2e11), got '" + assignment + "'");
  const std::string path = assignment.substr(0, eq);
  const std::string text = assignment.substr(eq + 1);
  if (path.empty()) throw InputError("--set", "missing key path before '=' in '" + assignment + "'");
  if (text.empty()) throw InputError("--set", "missing value after '=' in '" + assignment + "'");
  std::vector<std::string> segments;
  {
    std::size_t start = 0;
    while (true) {
      const auto dot = path.find('.', start);
      segments.push_back(path.substr(start, dot == std::string::npos ? std::string::npos : dot - start));
      if (segments.back().empty())
        throw InputError("--set", "empty segment in key path '" + path + "'");
      if (dot == std::string::npos) break;
      start = dot + 1;
    }
  }
  json value;
  try {
    value = parse_json_checked(text, "--set " + path, path, /*ignore_comments=*/false);
  } catch (const json::parse_error&) {
    value = text;  // not JSON: a plain string (e.g. --set solver.backend=ipopt)
  }
  if (document.is_null()) document = json::object();
  json* node = &document;
  std::string walked;
  for (std::size_t s = 0; s < segments.size(); ++s) {
    const std::string& seg = segments[s];
    if (node->is_null()) *node = json::object();
    json* next = nullptr;
    if (node->is_object()) {
      next = &(*node)[seg];
    } else if (node->is_array() && all_digits(seg)) {
      const auto idx = std::stoull(seg);
      if (idx >= node->size())
        throw InputError("--set", "index " + seg + " is out of range for '" + walked + "' (" +
                                      std::to_string(node->size()) + " entries)");
      next = &(*node)[idx];
    } else {
      throw InputError("--set", "'" + (walked.empty() ? std::string("(top level)") : walked) + "' is " +
                                    describe(*node) + ", not an object: cannot set '" + path + "'");
    }
    walked = join(walked, seg);
    if (s + 1 == segments.size()) *next = value;
    node = next;
  }
}

}  // namespace dc
