// The command line of every mdcs sub-command: one option table per sub-command drives both the parser and the
// `--help` text. Each option has a name, a kind (flag, integer, real, text, list of reals), a default, documented
// bounds and a help line; values are parsed strictly (no trailing garbage, no overflow, no NaN or infinity, the
// bounds checked) and every mistake is a Usage_error (exit code 2). Independent of CGAL, tested on its own
// (test/cli/test_cli_options.cpp).
#ifndef MDCS_CLI_OPTIONS_H
#define MDCS_CLI_OPTIONS_H

#include <algorithm>
#include <cctype>
#include <cerrno>
#include <cmath>
#include <cstdlib>
#include <limits>
#include <map>
#include <sstream>
#include <stdexcept>
#include <string>
#include <utility>
#include <vector>

namespace mdcs_cli {

// Exit codes, documented in `mdcs --help` and the README.
enum Exit_code { EXIT_OK = 0, EXIT_FAILURE_RUNTIME = 1, EXIT_USAGE = 2, EXIT_BAD_INPUT = 3, EXIT_INFEASIBLE = 4 };

// A wrong command line: printed with a pointer to the command's help, exit code 2.
struct Usage_error : std::runtime_error { using std::runtime_error::runtime_error; };

enum class Option_kind { flag, integer, real, text, list };

// One row of an option table.
struct Option_spec
{
  std::string name;       // without the leading "--"
  Option_kind kind = Option_kind::flag;
  std::string value_name; // shown in the help: --name VALUE
  std::string fallback;   // the default as text (empty: the option has no default; absent unless given)
  std::string help;       // one or more lines
  // integer, real, and every item of a list: inclusive bounds unless marked open
  double low = -std::numeric_limits<double>::infinity(), high = std::numeric_limits<double>::infinity();
  bool low_open = false;
  std::size_t min_items = 1, max_items = 1; // list
  std::vector<std::string> choices;         // text: the allowed values (empty: any non-empty text)
};

inline Option_spec flag_option(const std::string& name, const std::string& help)
{
  Option_spec o;
  o.name = name;
  o.kind = Option_kind::flag;
  o.help = help;
  return o;
}

// An integer in [low, high] (the bounds must be exact in a double: |bound| <= 2^53).
inline Option_spec integer_option(const std::string& name, const std::string& value_name, const std::string& fallback,
                                  double low, double high, const std::string& help)
{
  Option_spec o;
  o.name = name;
  o.kind = Option_kind::integer;
  o.value_name = value_name;
  o.fallback = fallback;
  o.low = low;
  o.high = high;
  o.help = help;
  return o;
}

// A finite real in [low, high], or (low, high] with low_open.
inline Option_spec real_option(const std::string& name, const std::string& value_name, const std::string& fallback,
                               double low, double high, const std::string& help, bool low_open = false)
{
  Option_spec o;
  o.name = name;
  o.kind = Option_kind::real;
  o.value_name = value_name;
  o.fallback = fallback;
  o.low = low;
  o.high = high;
  o.low_open = low_open;
  o.help = help;
  return o;
}

inline Option_spec text_option(const std::string& name, const std::string& value_name, const std::string& fallback,
                               const std::string& help, const std::vector<std::string>& choices = {})
{
  Option_spec o;
  o.name = name;
  o.kind = Option_kind::text;
  o.value_name = value_name;
  o.fallback = fallback;
  o.help = help;
  o.choices = choices;
  return o;
}

// A comma-separated list of min_items..max_items finite reals, each in [low, high].
inline Option_spec list_option(const std::string& name, const std::string& value_name, const std::string& fallback,
                               std::size_t min_items, std::size_t max_items, double low, double high,
                               const std::string& help)
{
  Option_spec o;
  o.name = name;
  o.kind = Option_kind::list;
  o.value_name = value_name;
  o.fallback = fallback;
  o.min_items = min_items;
  o.max_items = max_items;
  o.low = low;
  o.high = high;
  o.help = help;
  return o;
}

// A sub-command: its synopsis, what it does, its positional arguments and its option table.
struct Command_spec
{
  std::string name;        // "geodesics"
  std::string synopsis;    // after "usage: mdcs NAME "
  std::string description; // a paragraph
  std::vector<std::pair<std::string, std::string>> positionals; // name, help (for the help text)
  std::size_t min_positionals = 0, max_positionals = 0;
  std::vector<Option_spec> options;
  std::string notes; // printed after the options (file formats, exit codes)

  const Option_spec* find(const std::string& option) const
  {
    for(const Option_spec& o : options)
      if(o.name == option) return &o;
    return nullptr;
  }
};

namespace options_detail {

inline std::string number_text(double x)
{
  std::ostringstream s;
  s.precision(15);
  s << x;
  return s.str();
}

// Edit distance, for "did you mean --targets?".
inline std::size_t edit_distance(const std::string& a, const std::string& b)
{
  std::vector<std::size_t> row(b.size() + 1);
  for(std::size_t j = 0; j <= b.size(); ++j) row[j] = j;
  for(std::size_t i = 1; i <= a.size(); ++i) {
    std::size_t diagonal = row[0];
    row[0] = i;
    for(std::size_t j = 1; j <= b.size(); ++j) {
      const std::size_t up = row[j];
      row[j] = (std::min)({row[j] + 1, row[j - 1] + 1, diagonal + (a[i - 1] == b[j - 1] ? 0 : 1)});
      diagonal = up;
    }
  }
  return row[b.size()];
}

inline std::string bounds_text(const Option_spec& o)
{
  const bool has_low = std::isfinite(o.low), has_high = std::isfinite(o.high);
  if(has_low && has_high) return (o.low_open ? "> " + number_text(o.low) + " and <= " : number_text(o.low) + " to ") + number_text(o.high);
  if(has_low) return (o.low_open ? "> " : ">= ") + number_text(o.low);
  if(has_high) return "<= " + number_text(o.high);
  return "";
}

} // namespace options_detail

// Strict number parsing (also used for the comma-separated parts of other options). `what` names the value in
// the message, e.g. "--planes".
inline long long parse_integer_text(const std::string& text, const std::string& what, double low, double high)
{
  const std::size_t digits_from = !text.empty() && (text[0] == '-' || text[0] == '+') ? 1 : 0;
  if(text.size() == digits_from || text.find_first_not_of("0123456789", digits_from) != std::string::npos)
    throw Usage_error(what + ": '" + text + "' is not an integer");
  errno = 0;
  const long long v = std::strtoll(text.c_str(), nullptr, 10);
  const bool overflow = errno == ERANGE;
  Option_spec bounds;
  bounds.low = low;
  bounds.high = high;
  if(overflow || double(v) < low || double(v) > high)
    throw Usage_error(what + ": " + text + " is out of range (" + options_detail::bounds_text(bounds) + ")");
  return v;
}

inline double parse_real_text(const std::string& text, const std::string& what, double low, double high, bool low_open = false)
{
  // strtod skips leading white space and accepts "nan" and "inf": both refused here.
  if(text.empty() || std::isspace(static_cast<unsigned char>(text[0])))
    throw Usage_error(what + ": '" + text + "' is not a number");
  char* end = nullptr;
  errno = 0;
  const double v = std::strtod(text.c_str(), &end);
  if(end == text.c_str() || *end != '\0') throw Usage_error(what + ": '" + text + "' is not a number");
  if(errno == ERANGE && std::abs(v) < 1) // an underflow to a subnormal or 0 is a value nobody meant
    throw Usage_error(what + ": " + text + " is out of range (too close to 0 for a double)");
  if(errno == ERANGE) throw Usage_error(what + ": " + text + " is out of range for a double");
  if(!std::isfinite(v)) throw Usage_error(what + ": '" + text + "' is not a finite number");
  Option_spec bounds;
  bounds.low = low;
  bounds.high = high;
  bounds.low_open = low_open;
  if(v < low || v > high || (low_open && v == low))
    throw Usage_error(what + ": " + text + " is out of range (" + options_detail::bounds_text(bounds) + ")");
  return v;
}

// Comma-separated reals, e.g. "1,1,1" or "0,1,0,1".
inline std::vector<double> parse_real_list_text(const std::string& text, const std::string& what, std::size_t min_items,
                                                std::size_t max_items, double low, double high)
{
  std::vector<double> values;
  std::size_t start = 0;
  while(true) {
    const std::size_t comma = text.find(',', start);
    const std::string item = text.substr(start, comma == std::string::npos ? std::string::npos : comma - start);
    if(item.empty()) throw Usage_error(what + ": '" + text + "' has an empty item (expected numbers separated by commas)");
    values.push_back(parse_real_text(item, what, low, high));
    if(values.size() > max_items) break;
    if(comma == std::string::npos) break;
    start = comma + 1;
  }
  if(values.size() < min_items || values.size() > max_items) {
    const std::string count = min_items == max_items ? std::to_string(min_items)
                                                     : std::to_string(min_items) + " to " + std::to_string(max_items);
    throw Usage_error(what + ": '" + text + "' must have " + count + " comma-separated numbers");
  }
  return values;
}

// The options of one command line after parsing: every given value checked against its row; the defaults fill in.
class Parsed_options
{
public:
  Parsed_options() = default;
  Parsed_options(const Command_spec& spec, std::map<std::string, std::string> given, std::vector<std::string> positional)
    : spec_(&spec), given_(std::move(given)), positional_(std::move(positional))
  {}

  bool given(const std::string& name) const
  {
    row(name);
    return given_.count(name) != 0;
  }

  bool flag(const std::string& name) const
  {
    check_kind(name, Option_kind::flag);
    return given_.count(name) != 0;
  }

  long long integer(const std::string& name) const
  {
    const Option_spec& o = check_kind(name, Option_kind::integer);
    return parse_integer_text(value(name), "--" + name, o.low, o.high);
  }

  double real(const std::string& name) const
  {
    const Option_spec& o = check_kind(name, Option_kind::real);
    return parse_real_text(value(name), "--" + name, o.low, o.high, o.low_open);
  }

  // A text option's value; also the value of a list option as written (for messages).
  std::string text(const std::string& name) const
  {
    if(row(name).kind != Option_kind::list) check_kind(name, Option_kind::text);
    return value(name);
  }

  std::vector<double> list(const std::string& name) const
  {
    const Option_spec& o = check_kind(name, Option_kind::list);
    const std::string v = value(name);
    if(v.empty()) return {};
    return parse_real_list_text(v, "--" + name, o.min_items, o.max_items, o.low, o.high);
  }

  const std::vector<std::string>& positional() const { return positional_; }

  struct Effective_value
  {
    std::string name;
    Option_kind kind;
    std::string text; // flags: "true" / "false"
  };

  // Every option of the table with its effective value, in table order (an option without default that is not
  // given is left out). For the summaries.
  std::vector<Effective_value> effective() const
  {
    std::vector<Effective_value> all;
    if(!spec_) return all;
    for(const Option_spec& o : spec_->options) {
      if(o.name == "help" || o.name == "version") continue;
      if(o.kind == Option_kind::flag) all.push_back({o.name, o.kind, given_.count(o.name) ? "true" : "false"});
      else if(given_.count(o.name) || !o.fallback.empty()) all.push_back({o.name, o.kind, value(o.name)});
    }
    return all;
  }

private:
  const Option_spec& row(const std::string& name) const
  {
    const Option_spec* o = spec_ ? spec_->find(name) : nullptr;
    if(!o) throw std::logic_error("mdcs: the option --" + name + " is not in the table of this command");
    return *o;
  }
  const Option_spec& check_kind(const std::string& name, Option_kind kind) const
  {
    const Option_spec& o = row(name);
    if(o.kind != kind) throw std::logic_error("mdcs: the option --" + name + " is read as the wrong kind");
    return o;
  }
  std::string value(const std::string& name) const
  {
    const auto it = given_.find(name);
    return it != given_.end() ? it->second : row(name).fallback;
  }

  const Command_spec* spec_ = nullptr;
  std::map<std::string, std::string> given_;
  std::vector<std::string> positional_;
};

// Whether the command line asks for --help (or -h) or --version before any "--": answered before the rest is
// checked, so that `mdcs geodesics --help` works whatever else is on the line.
inline bool command_line_asks(int argc, char** argv, int first, const std::string& option)
{
  for(int i = first; i < argc; ++i) {
    const std::string a = argv[i];
    if(a == "--") return false;
    if(a == "--" + option || (option == "help" && a == "-h")) return true;
  }
  return false;
}

// Parses argv[first..argc) against the table: --name VALUE, --name=VALUE, --flag; "--" ends the options. A value
// option never takes a following "--..." as its value (write --name=--x for that), and a flag never takes one.
inline Parsed_options parse_command_line(const Command_spec& spec, int argc, char** argv, int first)
{
  std::map<std::string, std::string> given;
  std::vector<std::string> positional;
  bool options_ended = false;
  for(int i = first; i < argc; ++i) {
    const std::string a = argv[i];
    if(options_ended) {
      positional.push_back(a);
      continue;
    }
    if(a == "--") {
      options_ended = true;
      continue;
    }
    if(a.size() < 2 || a[0] != '-' || (a[1] != '-' && a != "-h")) {
      if(a.size() >= 2 && a[0] == '-' && !std::isdigit(static_cast<unsigned char>(a[1])) && a[1] != '.')
        throw Usage_error("unknown option '" + a + "' (options start with --)");
      positional.push_back(a);
      continue;
    }
    std::string name = a == "-h" ? "help" : a.substr(2), value;
    bool has_value = false;
    const auto eq = name.find('=');
    if(eq != std::string::npos) {
      value = name.substr(eq + 1);
      name = name.substr(0, eq);
      has_value = true;
    }
    const Option_spec* o = spec.find(name);
    if(!o) {
      std::string hint;
      std::size_t best = 3;
      for(const Option_spec& candidate : spec.options) {
        const std::size_t d = options_detail::edit_distance(name, candidate.name);
        if(d < best) best = d, hint = candidate.name;
      }
      throw Usage_error("unknown option --" + name + (hint.empty() ? std::string() : " (did you mean --" + hint + "?)"));
    }
    if(given.count(name)) throw Usage_error("option --" + name + " is given twice");
    if(o->kind == Option_kind::flag) {
      if(has_value) throw Usage_error("option --" + name + " takes no value (got '" + value + "')");
      given[name] = "true";
      continue;
    }
    if(!has_value) {
      if(i + 1 >= argc) throw Usage_error("option --" + name + " needs a value (" + o->value_name + ")");
      const std::string next = argv[i + 1];
      if(next.size() >= 2 && next[0] == '-' && next[1] == '-')
        throw Usage_error("option --" + name + " needs a value (" + o->value_name + "), got the option '" + next +
                          "' (write --" + name + "=" + next + " if that is the value)");
      value = next;
      ++i;
    }
    // Check the value now, so that every mistake is reported before any work starts.
    const std::string what = "--" + name;
    switch(o->kind) {
    case Option_kind::integer: parse_integer_text(value, what, o->low, o->high); break;
    case Option_kind::real: parse_real_text(value, what, o->low, o->high, o->low_open); break;
    case Option_kind::list: parse_real_list_text(value, what, o->min_items, o->max_items, o->low, o->high); break;
    case Option_kind::text:
      if(value.empty()) throw Usage_error(what + " needs a non-empty value");
      if(!o->choices.empty() && std::find(o->choices.begin(), o->choices.end(), value) == o->choices.end()) {
        std::string list;
        for(std::size_t k = 0; k < o->choices.size(); ++k) list += (k ? ", " : "") + o->choices[k];
        throw Usage_error(what + " must be one of " + list + " (got '" + value + "')");
      }
      break;
    case Option_kind::flag: break;
    }
    given[name] = value;
  }
  if(positional.size() < spec.min_positionals || positional.size() > spec.max_positionals) {
    std::string expected;
    for(const auto& p : spec.positionals) expected += (expected.empty() ? "" : " ") + p.first;
    if(spec.max_positionals == 0)
      throw Usage_error("unexpected argument '" + positional.front() + "' (mdcs " + spec.name + " takes options only)");
    if(positional.size() > spec.max_positionals)
      throw Usage_error("unexpected argument '" + positional[spec.max_positionals] + "' (expected " + expected + ")");
    throw Usage_error("missing argument " + expected);
  }
  return Parsed_options(spec, std::move(given), std::move(positional));
}

// The help text of a command, from its table.
inline std::string help_text(const Command_spec& spec)
{
  std::ostringstream out;
  out << "usage: mdcs " << spec.name << " " << spec.synopsis << "\n" << spec.description;
  if(!spec.description.empty() && spec.description.back() != '\n') out << "\n";
  const std::size_t column = 24;
  auto row = [&](const std::string& head, const std::string& text) {
    std::string h = "  " + head;
    std::istringstream lines(text);
    std::string line;
    bool first = true;
    while(std::getline(lines, line)) {
      if(first && h.size() + 1 > column) out << h << "\n" << std::string(column, ' ') << line << "\n";
      else if(first) out << h << std::string(column - h.size(), ' ') << line << "\n";
      else out << std::string(column, ' ') << line << "\n";
      first = false;
    }
    if(first) out << h << "\n";
  };
  for(const auto& p : spec.positionals) row(p.first, p.second);
  for(const Option_spec& o : spec.options) {
    std::string head = "--" + o.name + (o.kind == Option_kind::flag ? "" : " " + o.value_name);
    std::string text = o.help;
    std::string facts;
    if(!o.fallback.empty()) facts = "default " + o.fallback;
    const std::string bounds = o.kind == Option_kind::integer || o.kind == Option_kind::real ? options_detail::bounds_text(o) : "";
    if(!bounds.empty()) facts += (facts.empty() ? "" : "; ") + bounds;
    if(o.kind == Option_kind::list && !options_detail::bounds_text(o).empty())
      facts += (facts.empty() ? "" : "; ") + std::string("each ") + options_detail::bounds_text(o);
    if(!facts.empty()) text += " (" + facts + ")";
    row(head, text);
  }
  out << spec.notes;
  if(!spec.notes.empty() && spec.notes.back() != '\n') out << "\n";
  return out.str();
}

} // namespace mdcs_cli

#endif // MDCS_CLI_OPTIONS_H
