// The option-table parser of the mdcs tool (examples/mdcs/cli_options.h), its checked files (cli_output.h) and its
// JSON writer (cli_json.h): every malformed value is a Usage_error, bounds hold, flags never take the next argument,
// help text comes from the table, a failed write throws and leaves no file behind.
#include <catch2/catch.hpp>

#include "cli_json.h"
#include "cli_options.h"
#include "cli_output.h"

#include <cstdio>
#include <filesystem>
#include <fstream>
#include <limits>
#include <string>
#include <vector>

using namespace mdcs_cli;

namespace {

Command_spec test_spec()
{
  Command_spec s;
  s.name = "test";
  s.synopsis = "FILE [options]";
  s.description = "A test command.\n";
  s.positionals = {{"FILE", "a file"}};
  s.min_positionals = 0;
  s.max_positionals = 1;
  s.options = {
    integer_option("levels", "N", "20", 0, 1000, "iso lines"),
    real_option("limit", "D", "", 0, 1e300, "a distance limit"),
    real_option("alpha", "A", "0.1", 0, 1, "a weight", true),
    text_option("method", "M", "exact", "the method", {"exact", "fmm"}),
    text_option("name", "NAME", "", "a name"),
    list_option("view", "X,Y,Z", "1,1,1", 3, 3, -1e300, 1e300, "a direction"),
    flag_option("shorten-paths", "straighten"),
    flag_option("compare-exact", "compare"),
    flag_option("help", "help"),
  };
  return s;
}

Parsed_options parse(std::vector<std::string> args)
{
  static Command_spec spec = test_spec();
  std::vector<char*> argv;
  static std::string program = "mdcs";
  argv.push_back(&program[0]);
  for(std::string& a : args) argv.push_back(&a[0]);
  return parse_command_line(spec, int(argv.size()), argv.data(), 1);
}

bool rejects(std::vector<std::string> args)
{
  try {
    parse(args);
  } catch(const Usage_error&) {
    return true;
  }
  return false;
}

} // namespace

TEST_CASE("cli options: defaults and given values", "[cli][options]")
{
  const Parsed_options o = parse({"mesh.off", "--levels", "7", "--alpha=1", "--method", "fmm", "--view", "0,0,-2"});
  CHECK(o.positional() == std::vector<std::string>{"mesh.off"});
  CHECK(o.integer("levels") == 7);
  CHECK(o.real("alpha") == 1);
  CHECK(o.text("method") == "fmm");
  CHECK(o.list("view") == std::vector<double>{0, 0, -2});
  CHECK_FALSE(o.given("limit"));
  CHECK_FALSE(o.flag("shorten-paths"));
  const Parsed_options d = parse({});
  CHECK(d.integer("levels") == 20);
  CHECK(d.real("alpha") == Approx(0.1));
  CHECK(d.text("method") == "exact");
  CHECK(d.text("name").empty());
}

TEST_CASE("cli options: a flag never takes the next argument", "[cli][options]")
{
  // The README's `--method fmm --shorten-paths --compare-exact` once lost --compare-exact to --shorten-paths.
  const Parsed_options o = parse({"mesh.off", "--method", "fmm", "--shorten-paths", "--compare-exact"});
  CHECK(o.flag("shorten-paths"));
  CHECK(o.flag("compare-exact"));
  CHECK(o.positional().size() == 1);
  const Parsed_options p = parse({"--shorten-paths", "mesh.off"});
  CHECK(p.flag("shorten-paths"));
  CHECK(p.positional() == std::vector<std::string>{"mesh.off"});
  CHECK(rejects({"--shorten-paths=1"}));
}

TEST_CASE("cli options: a value option never swallows an option", "[cli][options]")
{
  CHECK(rejects({"--name", "--shorten-paths"}));
  CHECK(rejects({"--name"}));
  CHECK(parse({"--name=--odd"}).text("name") == "--odd");
  CHECK(parse({"--limit", "-0"}).real("limit") == 0); // a value may start with a single dash
  CHECK(rejects({"--limit", "-1"}));
}

TEST_CASE("cli options: integers are checked", "[cli][options]")
{
  CHECK(rejects({"--levels", "99999999999999999999"})); // overflow
  CHECK(rejects({"--levels", "1001"}));                 // above the documented bound
  CHECK(rejects({"--levels", "-1"}));
  CHECK(rejects({"--levels", "1e3"}));
  CHECK(rejects({"--levels", "12abc"}));
  CHECK(rejects({"--levels", " 12"}));
  CHECK(rejects({"--levels", ""}));
  CHECK(rejects({"--levels", "0x10"}));
  CHECK(parse({"--levels", "1000"}).integer("levels") == 1000);
  CHECK(parse({"--levels", "+0"}).integer("levels") == 0);
}

TEST_CASE("cli options: reals are checked", "[cli][options]")
{
  for(const char* bad : {"nan", "NaN", "inf", "-inf", "infinity", "1e400", "1e-400", "0.5x", "", " 0.5", "abc"})
    CHECK(rejects({"--alpha", bad}));
  CHECK(rejects({"--alpha", "0"}));   // open lower bound
  CHECK(rejects({"--alpha", "1.5"})); // above the bound
  CHECK(parse({"--alpha", "1e-3"}).real("alpha") == Approx(1e-3));
  CHECK(rejects({"--limit", "1e308"}));
  CHECK(parse({"--limit", "1e300"}).real("limit") == 1e300);
}

TEST_CASE("cli options: lists, choices, names, positionals", "[cli][options]")
{
  CHECK(rejects({"--view", "abc,xyz,1"}));
  CHECK(rejects({"--view", "1,1"}));
  CHECK(rejects({"--view", "1,1,1,7"}));
  CHECK(rejects({"--view", "1,,1"}));
  CHECK(rejects({"--view", "1,1,nan"}));
  CHECK(rejects({"--method", "heat"}));
  CHECK(rejects({"--method", ""}));
  CHECK(rejects({"--nosuch", "1"}));
  CHECK(rejects({"--levels", "1", "--levels", "2"})); // given twice
  CHECK(rejects({"a.off", "b.off"}));                  // one positional at most
  CHECK(rejects({"-x"}));
  const Parsed_options o = parse({"--", "--odd-file-name"});
  CHECK(o.positional() == std::vector<std::string>{"--odd-file-name"});
  try {
    parse({"--levles", "3"});
    FAIL("accepted an unknown option");
  } catch(const Usage_error& e) {
    CHECK(std::string(e.what()).find("did you mean --levels?") != std::string::npos);
  }
}

TEST_CASE("cli options: help and effective values come from the table", "[cli][options]")
{
  const Command_spec spec = test_spec();
  const std::string help = help_text(spec);
  CHECK(help.find("usage: mdcs test FILE [options]") != std::string::npos);
  CHECK(help.find("--levels N") != std::string::npos);
  CHECK(help.find("default 20; 0 to 1000") != std::string::npos);
  CHECK(help.find("> 0 and <= 1") != std::string::npos);
  CHECK(help.find("--shorten-paths") != std::string::npos);
  const auto effective = parse({"--levels", "3"}).effective();
  bool levels = false, flag = false;
  for(const auto& v : effective) {
    if(v.name == "levels") levels = v.text == "3" && v.kind == Option_kind::integer;
    if(v.name == "compare-exact") flag = v.text == "false";
    CHECK(v.name != "limit"); // no default, not given
  }
  CHECK(levels);
  CHECK(flag);
  char program[] = "mdcs", cmd[] = "test", opt[] = "--help", dashdash[] = "--", late[] = "--help";
  char* argv[] = {program, cmd, opt};
  CHECK(command_line_asks(3, argv, 2, "help"));
  char* argv2[] = {program, cmd, dashdash, late};
  CHECK_FALSE(command_line_asks(4, argv2, 2, "help"));
}

TEST_CASE("cli output: names stay inside the output folder", "[cli][output]")
{
  CHECK(checked_file_name("curve_1.b", "--name") == "curve_1.b");
  for(const char* bad : {"../x", "a/b", "..", ".hidden", "-x", "", "a b", "a\\b"})
    CHECK_THROWS_AS(checked_file_name(bad, "--name"), Usage_error);
  CHECK_THROWS_AS(checked_file_name(std::string(101, 'a'), "--name"), Usage_error);
}

TEST_CASE("cli output: checked files", "[cli][output]")
{
  const std::filesystem::path dir = std::filesystem::temp_directory_path() / "mdcs_test_cli_output";
  std::filesystem::remove_all(dir);
  std::filesystem::create_directories(dir);
  const std::string path = (dir / "a.txt").string();
  {
    Output_file f(path);
    f << "x " << 0.1 << "\n";
    CHECK_FALSE(std::filesystem::exists(path)); // written as .part until committed
    f.commit();
  }
  std::ifstream in(path);
  std::string line;
  std::getline(in, line);
  CHECK(line == "x 0.10000000000000001"); // 17 significant digits by default
  {
    Output_file g((dir / "b.txt").string());
    g << "never committed";
  }
  CHECK_FALSE(std::filesystem::exists(dir / "b.txt"));
  CHECK_FALSE(std::filesystem::exists(dir / "b.txt.part"));
  // A device that is always full: the failure is reported, not swallowed.
  if(std::filesystem::exists("/dev/full")) {
    Output_file full("/dev/full");
    full << std::string(1 << 17, 'x');
    CHECK_THROWS_WITH(full.commit(), Catch::Contains("No space left on device"));
  }
  CHECK_THROWS_AS(Output_file((dir / "missing" / "c.txt").string()), std::runtime_error);
  CHECK_THROWS_AS(Output_file(dir.string()), std::runtime_error);
  std::filesystem::remove_all(dir);
}

TEST_CASE("cli json: strings, numbers and objects", "[cli][json]")
{
  CHECK(json_string("a\"b\\c\n\x01") == "\"a\\\"b\\\\c\\n\\u0001\"");
  CHECK(json_number(0.1) == "0.10000000000000001");
  CHECK(json_number(std::numeric_limits<double>::infinity()) == "null");
  CHECK(json_number(std::numeric_limits<double>::quiet_NaN()) == "null");
  Json_object inner, outer;
  inner.add("n", 3);
  outer.add("inner", inner).add("ok", true).raw("list", json_numbers({1, 2}));
  CHECK(outer.text() == "{\n  \"inner\": {\n    \"n\": 3\n  },\n  \"ok\": true,\n  \"list\": [1,2]\n}");
}
