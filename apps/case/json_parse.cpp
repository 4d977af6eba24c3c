// A SAX handler over nlohmann's DOM builder that checks depth, duplicate keys and number range
// while parsing, so a hostile document is rejected before a deep tree is ever built.
#include "json_parse.hpp"

#include <set>
#include <vector>

#include "errors.hpp"

namespace dc::case_json {
namespace {

using json = nlohmann::json;

class CheckedSax : public nlohmann::detail::json_sax_dom_parser<json> {
  using Base = nlohmann::detail::json_sax_dom_parser<json>;

 public:
  CheckedSax(json& result, std::string origin, std::string base)
      : Base(result, /*allow_exceptions=*/true), origin_(std::move(origin)), base_(std::move(base)) {}

  bool null() { return next(), Base::null(); }
  bool boolean(bool v) { return next(), Base::boolean(v); }
  bool number_integer(json::number_integer_t v) { return next(), Base::number_integer(v); }
  bool number_unsigned(json::number_unsigned_t v) { return next(), Base::number_unsigned(v); }
  bool number_float(json::number_float_t v, const json::string_t& s) { return next(), Base::number_float(v, s); }
  bool string(json::string_t& v) { return next(), Base::string(v); }
  bool binary(json::binary_t& v) { return next(), Base::binary(v); }

  bool start_object(std::size_t n) {
    open(false);
    return Base::start_object(n);
  }
  bool key(json::string_t& k) {
    Level& level = stack_.back();
    level.key = k;
    if (!level.keys.insert(k).second)
      throw InputError(path(), "duplicate key (each key may appear once in an object)");
    return Base::key(k);
  }
  bool end_object() {
    stack_.pop_back();
    return Base::end_object();
  }
  bool start_array(std::size_t n) {
    open(true);
    return Base::start_array(n);
  }
  bool end_array() {
    stack_.pop_back();
    return Base::end_array();
  }

  template <class Exception>
  bool parse_error(std::size_t position, const std::string& token, const Exception& ex) {
    if (ex.id == 406)  // out_of_range: number overflow (the token is the number's text)
      throw InputError(path(/*pending=*/true), "the number " + token + " is outside the range of a double");
    return Base::parse_error(position, token, ex);
  }

 private:
  struct Level {
    bool array = false;
    std::size_t count = 0;  ///< array: values seen
    std::string key;        ///< object: the current key
    std::set<std::string> keys;
  };

  /// A value starts: in an array it is the next element.
  void next() {
    if (!stack_.empty() && stack_.back().array) ++stack_.back().count;
  }

  void open(bool array) {
    next();
    if (static_cast<int>(stack_.size()) >= kMaxJsonDepth)
      throw InputError(path(), "nested more than " + std::to_string(kMaxJsonDepth) +
                                   " levels deep (arrays and objects); a case needs a few");
    stack_.push_back({array, 0, {}, {}});
  }

  /// The key path of the current value (`pending`: of the value about to be read).
  std::string path(bool pending = false) const {
    std::string p = base_;
    for (std::size_t i = 0; i < stack_.size(); ++i) {
      const Level& level = stack_[i];
      if (p.size() > 160) return p + "...";
      if (level.array) {
        const bool ahead = pending && i + 1 == stack_.size();  // the element not counted yet
        const std::size_t index = level.count - (level.count > 0 && !ahead ? 1 : 0);
        p += "[" + std::to_string(index) + "]";
      } else if (!level.key.empty() || !level.keys.empty()) {
        p += (p.empty() ? "" : ".") + level.key;
      }
    }
    return p.empty() ? origin_ : p;
  }

  std::vector<Level> stack_;
  std::string origin_, base_;
};

}  // namespace

json parse_json_checked(const std::string& text, const std::string& origin, const std::string& base_path,
                        bool ignore_comments) {
  json result;
  CheckedSax sax(result, origin, base_path);
  json::sax_parse(text, &sax, json::input_format_t::json, /*strict=*/true, ignore_comments);
  return result;
}

}  // namespace dc::case_json
