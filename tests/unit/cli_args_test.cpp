// The `toon` CLI without a daemon: argument parsing, --set against the
// schema, bundle discovery on disk, and the wording of server errors.
#include "cli_args.h"
#include "cli_test_helpers.h"

#include <gtest/gtest.h>
#include <unistd.h>

#include <algorithm>
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <optional>
#include <string>
#include <vector>

#include "bundle_scan.h"
#include "cli_flags.h"
#include "gallery_looks.h"
#include "help_checks.h"
#include "param_schema.h"
#include "reply.h"
#include "sheet_output.h"
#include "support/shared_models.h"

namespace toond::cli {
namespace {

namespace fs = std::filesystem;
using nlohmann::json;
using Args = std::vector<std::string>;

const proto::ParamSchema& schema() { return proto::ParamSchema::render_params(); }

Options parse(const Args& args, std::optional<std::string> env = std::nullopt) { return parse_args(args, env); }

using cli_test::contains;
using cli_test::TempDir;
using cli_test::usage_error;

// ---------------------------------------------------------------- --server

TEST(CliArgs, ServerBeforeVerb) {
  const Options o = parse({"--server", "http://10.0.0.5:9000", "health"});
  EXPECT_EQ(o.verb, Verb::health);
  EXPECT_EQ(o.server, "http://10.0.0.5:9000");
}

TEST(CliArgs, ServerAfterVerbAndEqualsForm) {
  const Options o = parse({"render", "--model", "0123456789abcdef", "-o", "x.png", "--server=http://renderhost:81"});
  EXPECT_EQ(o.verb, Verb::render);
  EXPECT_EQ(o.server, "http://renderhost:81");
}

TEST(CliArgs, ServerDefaultsWithoutFlagOrEnvironment) {
  EXPECT_EQ(parse({"health"}).server, "http://127.0.0.1:8080");
  EXPECT_EQ(parse({"health"}, std::string()).server, "http://127.0.0.1:8080");
}

TEST(CliArgs, ServerFromEnvironmentUnlessFlagGiven) {
  EXPECT_EQ(parse({"health"}, "http://env-host:7000").server, "http://env-host:7000");
  EXPECT_EQ(parse({"health", "--server", "http://flag:1"}, "http://env-host:7000").server, "http://flag:1");
}

TEST(CliArgs, ToondUrlIsReadFromTheProcessEnvironment) {
  const char* saved = std::getenv("TOOND_URL");
  const std::optional<std::string> restore = saved ? std::optional<std::string>(saved) : std::nullopt;
  ::setenv("TOOND_URL", "http://from-env:1234", 1);
  EXPECT_EQ(parse({"health"}, server_from_environment()).server, "http://from-env:1234");
  ::setenv("TOOND_URL", "", 1);
  EXPECT_EQ(server_from_environment(), std::nullopt);
  ::unsetenv("TOOND_URL");
  EXPECT_EQ(server_from_environment(), std::nullopt);
  if (restore) ::setenv("TOOND_URL", restore->c_str(), 1);
}

TEST(CliArgs, TrailingSlashOfServerIsDropped) {
  EXPECT_EQ(parse({"health", "--server", "http://h:1/"}).server, "http://h:1");
}

TEST(CliArgs, BadServerUrlsAreUsageErrors) {
  for (const char* url :
       {"ftp://h", "127.0.0.1:8080", "http://", "http://h:99999", "http://h:x", "http://h:8080/?q=1"}) {
    EXPECT_FALSE(usage_error([&] { parse({"health", "--server", url}); }).empty()) << url;
  }
  EXPECT_FALSE(usage_error([] { parse({"health"}, "not a url"); }).empty());
}

TEST(CliArgs, ServerUrlKeepsAPathPrefixForProxies) {
  const ServerUrl u = parse_server_url("https://example.org/toond/");
  EXPECT_EQ(u.scheme_host_port, "https://example.org");
  EXPECT_EQ(u.base_path, "/toond");
  const ServerUrl v = parse_server_url("http://[::1]:8080");
  EXPECT_EQ(v.scheme_host_port, "http://[::1]:8080");
  EXPECT_EQ(v.base_path, "");
}

TEST(CliArgs, ServerGivenTwiceIsRejected) {
  EXPECT_TRUE(contains(usage_error([] {
                         parse({"--server", "http://a:1", "health", "--server", "http://b:2"});
                       }),
                       "twice"));
}

// ---------------------------------------------------------------- verbs

TEST(CliArgs, NoVerbOrUnknownVerbOrOptionIsRejected) {
  EXPECT_TRUE(contains(usage_error([] { parse({}); }), "no command"));
  EXPECT_TRUE(contains(usage_error([] { parse({"rendr"}); }), "unknown command 'rendr'"));
  EXPECT_TRUE(contains(usage_error([] { parse({"health", "--frobnicate"}); }), "--frobnicate"));
}

TEST(CliArgs, FlagsOfOneVerbAreRejectedOnAnother) {
  EXPECT_TRUE(contains(usage_error([] { parse({"health", "-o", "x.png"}); }), "health does not take -o"));
  EXPECT_TRUE(contains(usage_error([] { parse({"upload", "a.obj", "--set", "width=5"}); }), "--set"));
  EXPECT_TRUE(contains(usage_error([] { parse({"render", "-q", "-o", "x.png"}); }), "--quiet"));
  EXPECT_FALSE(usage_error([] { parse({"health", "extra"}); }).empty());
}

TEST(CliArgs, UploadTakesExactlyOnePath) {
  const Options o = parse({"upload", "-q", "models/spot.obj"});
  EXPECT_EQ(o.verb, Verb::upload);
  EXPECT_EQ(o.obj_path, "models/spot.obj");
  EXPECT_TRUE(o.quiet);
  EXPECT_FALSE(usage_error([] { parse({"upload"}); }).empty());
  EXPECT_FALSE(usage_error([] { parse({"upload", "a.obj", "b.obj"}); }).empty());
}

TEST(CliArgs, UploadPicksAGltfSceneByIndex) {
  EXPECT_EQ(parse({"upload", "--scene", "2", "m.glb"}).scene, "2");
  EXPECT_TRUE(parse({"upload", "m.glb"}).scene.empty());
  for (const char* bad : {"-1", "x", "", "1.5"}) {
    EXPECT_TRUE(contains(usage_error([bad] { parse({"upload", "--scene", bad, "m.glb"}); }), "--scene")) << bad;
  }
  EXPECT_TRUE(contains(usage_error([] { parse({"render", "--scene", "1", "-o", "x.png"}); }), "--scene"));
}

TEST(CliArgs, UploadTakesTheSmoothingAngleAndTheUpAxis) {
  const auto options = parse({"upload", "--smooth-angle", "45", "--up", "z", "part.obj"});
  EXPECT_EQ(options.smooth_angle, "45");
  EXPECT_EQ(options.up, "z");
  EXPECT_TRUE(parse({"upload", "part.obj"}).smooth_angle.empty());
  for (const char* bad : {"-1", "181", "x", ""}) {
    EXPECT_TRUE(contains(usage_error([bad] {
                           parse({"upload", "--smooth-angle", bad, "m.obj"});
                         }),
                         "--smooth-angle"))
        << bad;
  }
  EXPECT_TRUE(contains(usage_error([] { parse({"upload", "--up", "x", "m.obj"}); }), "--up"));
  EXPECT_TRUE(contains(usage_error([] { parse({"render", "--up", "z", "-o", "x.png"}); }), "--up"));
}

TEST(CliArgs, RenderRequiresOutput) {
  EXPECT_TRUE(contains(usage_error([] { parse({"render", "spot.obj"}); }), "-o"));
  EXPECT_TRUE(contains(usage_error([] { parse({"render", "-o"}); }), "needs a value"));
}

TEST(CliArgs, RenderRejectsPathTogetherWithModel) {
  EXPECT_TRUE(contains(usage_error([] {
                         parse({"render", "spot.obj", "--model", "0123456789abcdef", "-o", "x.png"});
                       }),
                       "not both"));
}

TEST(CliArgs, RenderForms) {
  const Options demo = parse({"render", "-o", "demo.png"});
  EXPECT_TRUE(demo.obj_path.empty());
  EXPECT_TRUE(demo.model_id.empty());
  EXPECT_EQ(demo.output, "demo.png");

  const Options local = parse({"render", "spot/spot.obj", "--out=spot.png", "--params", "p.json"});
  EXPECT_EQ(local.obj_path, "spot/spot.obj");
  EXPECT_EQ(local.output, "spot.png");
  EXPECT_EQ(local.params_file, "p.json");

  const Options piped = parse({"render", "--model=0123456789abcdef", "-o", "-"});
  EXPECT_EQ(piped.model_id, "0123456789abcdef");
  EXPECT_EQ(piped.output, "-");

  // After `--` a name that starts with '-' is a path, not an option.
  EXPECT_EQ(parse({"render", "-o", "x.png", "--", "-odd.obj"}).obj_path, "-odd.obj");
}

// --output names the layer, as --set output=LAYER does; a file name there
// (the flag's old meaning) is pointed at -o.
TEST(CliArgs, OutputNamesTheLayer) {
  const Options lines = parse({"render", "--output", "lines", "-o", "lines.png"});
  ASSERT_EQ(lines.sets.size(), 1u);
  EXPECT_EQ(lines.sets[0], (std::pair<std::string, std::string>{"output", "lines"}));
  EXPECT_EQ(lines.output, "lines.png");
  for (const char* file : {"x.png", "-", "out/x"}) {
    EXPECT_TRUE(contains(usage_error([&] { parse({"render", "--output", file}); }), "-o FILE")) << file;
  }
}

TEST(CliArgs, SetNeedsKeyEqualsValue) {
  EXPECT_TRUE(contains(usage_error([] { parse({"render", "-o", "x", "--set", "outline.width"}); }), "key.sub=value"));
  EXPECT_FALSE(usage_error([] { parse({"render", "-o", "x", "--set", "=3"}); }).empty());
  const Options o = parse({"render", "-o", "x", "--set=background=[1,1,1]"});
  ASSERT_EQ(o.sets.size(), 1u);
  EXPECT_EQ(o.sets[0].first, "background");
  EXPECT_EQ(o.sets[0].second, "[1,1,1]");
}

TEST(CliArgs, HelpAndVersionNeedNothingElse) {
  Options o = parse({"--help"});
  EXPECT_TRUE(o.help);
  EXPECT_EQ(o.verb, Verb::none);
  o = parse({"render", "-h"});
  EXPECT_TRUE(o.help);
  EXPECT_EQ(o.verb, Verb::render);
  o = parse({"help", "upload"});
  EXPECT_TRUE(o.help);
  EXPECT_EQ(o.verb, Verb::upload);
  // A broken TOOND_URL must not stand in the way of reading the help.
  EXPECT_TRUE(parse({"--help"}, "garbage").help);
  EXPECT_TRUE(parse({"--version"}).version);
}

TEST(CliArgs, UsageTextListsVerbsAndFlags) {
  const std::string all = usage_text(Verb::none);
  for (const char* word : {"health", "upload", "render", "--server", "TOOND_URL", "--help", "--version"}) {
    EXPECT_TRUE(contains(all, word)) << word;
  }
  const std::string render = usage_text(Verb::render);
  for (const char* word : {"--model", "--params", "--set", "-o"}) {
    EXPECT_TRUE(contains(render, word)) << word;
  }
  EXPECT_TRUE(contains(usage_text(Verb::upload), "--quiet"));
}

// Whether `toon VERB NAME [x]` gets past NAME: the parser knows the flag and
// lets VERB take it. Other complaints (no path, a bad value) are not its.
bool verb_takes(Verb verb, const std::string& name) {
  Args args;
  if (verb != Verb::none) args.emplace_back(verb_name(verb));
  args.push_back(name);
  std::string error = usage_error([&] { parse(args); });
  if (contains(error, "needs a value")) {
    args.push_back("x");
    error = usage_error([&] { parse(args); });
  }
  return !contains(error, "unknown option") && !contains(error, "does not take");
}

// --help and the parser read one table (cli_flags.h); this checks that what
// they make of it agrees. Every flag the parser takes with a verb is in that
// verb's option list (a global one in the overview's), and every option a
// help text names, in its lists, synopses or prose, is one the parser takes
// there.
TEST(CliArgs, HelpNamesExactlyTheFlagsTheParserTakes) {
  std::vector<Verb> all_verbs = {Verb::none};
  for (const VerbInfo& v : verbs()) all_verbs.push_back(v.verb);
  for (const Flag& flag : flags()) {
    for (const Verb verb : all_verbs) {
      const bool listed_here =
          flag.verbs == kGlobal ? verb == Verb::none : verb != Verb::none && (flag.verbs & verb_set(verb)) != 0;
      if (!listed_here) continue;
      EXPECT_TRUE(contains(usage_text(verb), "\n  " + flag.help.written() + " "))
          << verb_name(verb) << " --help lacks " << flag.help.written();
      for (const std::string_view name : {flag.help.alias, flag.help.name}) {
        if (!name.empty()) {
          EXPECT_TRUE(verb_takes(verb, std::string(name))) << verb_name(verb) << " " << name;
        }
      }
    }
  }
  for (const Verb verb : all_verbs) {
    for (const std::string& name : help_checks::options_named_in(usage_text(verb))) {
      EXPECT_TRUE(verb_takes(verb, name)) << "toon " << verb_name(verb) << " --help names " << name;
    }
  }
}

TEST(CliArgs, HelpStatesTheDefaultsInForce) {
  EXPECT_TRUE(contains(usage_text(Verb::none), std::string(kDefaultServer)));
  const std::string gallery = usage_text(Verb::gallery);
  EXPECT_TRUE(contains(gallery, std::string(kDefaultModelsDir)));
  EXPECT_TRUE(contains(gallery, "(default " + std::to_string(kDefaultGallerySize) + ")"));
  for (const std::string& name : gallery::default_model_names()) EXPECT_TRUE(contains(gallery, name)) << name;
}

// ---------------------------------------------------------------- render parameters

TEST(RenderParams, RepeatedSetsMergeAndLaterOnesWin) {
  const Options o = parse({"render", "-o", "x.png", "--set", "outline.width=3", "--set", "outline.color=[1,0,0]",
                           "--set", "shading.steps=5", "--set", "outline.width=4.5", "--set", "outline.enabled=false"});
  const json p = build_render_params(o, schema());
  EXPECT_EQ(p, json::parse(R"({"outline":{"width":4.5,"color":[1,0,0],"enabled":false},
                               "shading":{"steps":5}})"));
}

// -o NAME.svg asks for the lines as vectors; parameters that ask for
// another output contradict it.
TEST(RenderParams, AnSvgFileNameAsksForOutputSvg) {
  EXPECT_EQ(build_render_params(parse({"render", "-o", "lines.SVG"}), schema()), json::parse(R"({"output":"svg"})"));
  EXPECT_EQ(build_render_params(parse({"render", "-o", "x.svg", "--set", "svg.hidden=true"}), schema()),
            json::parse(R"({"output":"svg","svg":{"hidden":true}})"));
  EXPECT_EQ(build_render_params(parse({"render", "-o", "x.png"}), schema()), json::object());
  const std::string message = usage_error([&] {
    build_render_params(parse({"render", "-o", "x.svg", "--output", "lines"}), schema());
  });
  EXPECT_TRUE(contains(message, "x.svg")) << message;
  EXPECT_TRUE(contains(message, "\"lines\"")) << message;
}

// Keys as users type them, driven by the schema: a path through objects
// and through fields that are an object or a list of them
// (sheet.animation), a comma list where the field takes a list, a name or
// an index where it takes either.
TEST(RenderParams, SetWalksIntoFieldsOfAlternativesAndTakesCommaLists) {
  const Options o = parse({"render", "-o", "x.png", "--set", "sheet.animation.clip=walk", "--set",
                           "sheet.animation.frames=8", "--set", "outline.method=hull,edges", "--set",
                           "background=1,1,0.5", "--set", "lights.0.direction=0,0,-1", "--set", "animation.clip=2"});
  const json p = build_render_params(o, schema());
  EXPECT_EQ(p["sheet"]["animation"], json::parse(R"({"clip":"walk","frames":8})"));
  EXPECT_EQ(p["outline"]["method"], json::parse(R"(["hull","edges"])"));
  EXPECT_EQ(p["background"], json::parse("[1,1,0.5]"));
  EXPECT_EQ(p["lights"][0]["direction"], json::parse("[0,0,-1]"));
  EXPECT_EQ(p["animation"]["clip"], 2);  // an index, not the name "2"

  const Options listed = parse({"render", "-o", "x.png", "--set", "sheet.animation.0.clip=walk", "--set",
                                "sheet.animation.1.clip=Armature|Run", "--set", "outline.method=edges", "--set",
                                "outline.method=[\"hull\"]"});
  const json q = build_render_params(listed, schema());
  EXPECT_EQ(q["sheet"]["animation"], json::parse(R"([{"clip":"walk"},{"clip":"Armature|Run"}])"));
  EXPECT_EQ(q["outline"]["method"], json::parse(R"(["hull"])"));  // JSON still works

  const Options bad_item = parse({"render", "-o", "x.png", "--set", "outline.method=hull,brush"});
  EXPECT_TRUE(contains(usage_error([&] { build_render_params(bad_item, schema()); }), "/outline/method"));
  const Options bad_number = parse({"render", "-o", "x.png", "--set", "background=1,one,1"});
  const std::string number_message = usage_error([&] { build_render_params(bad_number, schema()); });
  EXPECT_TRUE(contains(number_message, "background=1,one,1")) << number_message;
  EXPECT_TRUE(contains(number_message, "comma-separated list")) << number_message;
  const Options unknown = parse({"render", "-o", "x.png", "--set", "sheet.animation.speed=2"});
  EXPECT_TRUE(contains(usage_error([&] { build_render_params(unknown, schema()); }), "unknown"));
}

// A clip's range as users type it: two numbers in seconds, or in frames
// (168f,187f) where the clip has a frame rate, which the daemon's answer
// for the model lists; the frames become seconds before the request goes.
TEST(RenderParams, ARangeIsSecondsOrFramesOfAClipWithAFrameRate) {
  const Options seconds = parse({"render", "-o", "x.png", "--set", "sheet.animation.clip=walk", "--set",
                                 "sheet.animation.range=5.6,6.23", "--set", "sheet.animation.loop=false"});
  EXPECT_EQ(build_render_params(seconds, schema())["sheet"]["animation"],
            json::parse(R"({"clip":"walk","range":[5.6,6.23],"loop":false})"));

  std::vector<std::string> asked;
  const ClipsOfModel clips = [&](const std::string& id) {
    asked.push_back(id);
    return json::parse(R"([{"name":"anim","duration":3.67,"frame_rate":60},
                           {"name":"Armature|Walk","duration":1.0}])");
  };
  const Options frames = parse({"render", "-o", "x.png", "--model", "0123456789abcdef", "--set",
                                "sheet.animation.range=168f,187f", "--set", "sheet.animation.clip=anim", "--set",
                                "animation.clip=0", "--set", "animation.range=[ 0f, 30f ]"});
  const json p = build_render_params(frames, schema(), clips);
  EXPECT_EQ(asked, (std::vector<std::string>{"0123456789abcdef", "0123456789abcdef"}));
  EXPECT_EQ(p["sheet"]["animation"]["range"], json::parse("[2.8, 3.1166666666666667]"));
  EXPECT_EQ(p["animation"]["range"], json::parse("[0, 0.5]"));

  const auto refused = [&](const Args& args) {
    return usage_error([&] { build_render_params(parse(args), schema(), clips); });
  };
  const std::string by_seconds = refused({"render", "-o", "x.png", "--model", "0123456789abcdef", "--set",
                                          "animation.clip=Walk", "--set", "animation.range=1f,2f"});
  EXPECT_TRUE(contains(by_seconds, "no frame rate")) << by_seconds;
  EXPECT_TRUE(contains(by_seconds, "animation.range=1f,2f")) << by_seconds;
  const std::string no_model =
      refused({"render", "-o", "x.png", "--set", "animation.clip=anim", "--set", "animation.range=1f,2f"});
  EXPECT_TRUE(contains(no_model, "--model ID")) << no_model;
  const std::string no_clip =
      refused({"render", "-o", "x.png", "--model", "0123456789abcdef", "--set", "animation.range=1f,2f"});
  EXPECT_TRUE(contains(no_clip, "--set animation.clip=NAME")) << no_clip;
  const std::string unknown = refused({"render", "-o", "x.png", "--model", "0123456789abcdef", "--set",
                                       "animation.clip=run", "--set", "animation.range=1f,2f"});
  EXPECT_TRUE(contains(unknown, "no clip \"run\"")) << unknown;
  const std::string mixed = refused({"render", "-o", "x.png", "--model", "0123456789abcdef", "--set",
                                     "animation.clip=anim", "--set", "animation.range=1f,2"});
  EXPECT_TRUE(contains(mixed, "both ends in frames")) << mixed;
}

TEST(RenderParams, UnknownKeyIsRejectedNamingIt) {
  const Options o = parse({"render", "-o", "x.png", "--set", "outline.widht=3"});
  const std::string message = usage_error([&] { build_render_params(o, schema()); });
  EXPECT_TRUE(contains(message, "outline.widht")) << message;
  EXPECT_TRUE(contains(message, "unknown")) << message;

  const Options top = parse({"render", "-o", "x.png", "--set", "colour=1"});
  EXPECT_TRUE(contains(usage_error([&] { build_render_params(top, schema()); }), "colour"));
}

TEST(RenderParams, BadValueTypeIsRejectedNamingTheKey) {
  for (const Args& args : std::vector<Args>{{"--set", "outline.width=thick"},
                                            {"--set", "shading.steps=2.5"},
                                            {"--set", "outline.enabled=maybe"},
                                            {"--set", "background=[1,1"}}) {
    Args full = {"render", "-o", "x.png"};
    full.insert(full.end(), args.begin(), args.end());
    const Options o = parse(full);
    const std::string message = usage_error([&] { build_render_params(o, schema()); });
    const std::string key = o.sets[0].first;
    EXPECT_TRUE(contains(message, key)) << args[1] << " -> " << message;
  }
}

TEST(RenderParams, OutOfRangeAndEnumAreCaughtLocally) {
  const Options wide = parse({"render", "-o", "x.png", "--set", "outline.width=100"});
  EXPECT_TRUE(contains(usage_error([&] { build_render_params(wide, schema()); }), "/outline/width"));
  const Options msaa = parse({"render", "-o", "x.png", "--set", "msaa=3"});
  EXPECT_TRUE(contains(usage_error([&] { build_render_params(msaa, schema()); }), "/msaa"));
  const Options mode = parse({"render", "-o", "x.png", "--set", "shading.mode=watercolor"});
  EXPECT_TRUE(contains(usage_error([&] { build_render_params(mode, schema()); }), "/shading/mode"));
}

TEST(RenderParams, SettingInsideTheDefaultLightKeepsItsOtherFields) {
  const Options o = parse({"render", "-o", "x.png", "--set", "lights.0.intensity=2"});
  const json p = build_render_params(o, schema());
  ASSERT_TRUE(p["lights"].is_array());
  ASSERT_EQ(p["lights"].size(), 1u);
  EXPECT_EQ(p["lights"][0]["type"], "directional");
  EXPECT_TRUE(p["lights"][0].contains("direction"));
  EXPECT_EQ(p["lights"][0]["intensity"], 2.0);
}

TEST(RenderParams, ModelIdIsSetAndChecked) {
  const Options o = parse({"render", "--model", "0123456789abcdef0123", "-o", "x.png"});
  EXPECT_EQ(build_render_params(o, schema())["model"], "0123456789abcdef0123");
  const Options bad = parse({"render", "--model", "not-an-id", "-o", "x.png"});
  EXPECT_TRUE(contains(usage_error([&] { build_render_params(bad, schema()); }), "/model"));
}

TEST(RenderParams, ParamsFileIsTheBaseAndSetsOverrideIt) {
  TempDir dir;
  const fs::path file = dir.write("p.json", R"({"width":320,"outline":{"width":1,"color":[0,0,1]}})");
  const Options o = parse({"render", "--params", file.string(), "--set", "outline.width=6", "-o", "x.png"});
  const json p = build_render_params(o, schema());
  EXPECT_EQ(p["width"], 320);
  EXPECT_EQ(p["outline"]["width"], 6.0);
  EXPECT_EQ(p["outline"]["color"], json::parse("[0,0,1]"));
}

TEST(RenderParams, BrokenParamsFilesAreUsageErrors) {
  TempDir dir;
  const auto message_for = [&](const std::string& content) {
    const fs::path file = dir.write("p.json", content);
    const Options o = parse({"render", "--params", file.string(), "-o", "x.png"});
    return usage_error([&] { build_render_params(o, schema()); });
  };
  EXPECT_TRUE(contains(message_for("{\"width\": 320,"), "not valid JSON"));
  EXPECT_TRUE(contains(message_for("[1,2,3]"), "JSON object"));
  EXPECT_TRUE(contains(message_for(R"({"outline":{"thickness":2}})"), "/outline/thickness"));

  const Options missing = parse({"render", "--params", (dir.path() / "nope.json").string(), "-o", "x"});
  EXPECT_TRUE(contains(usage_error([&] { build_render_params(missing, schema()); }), "nope.json"));
}

TEST(RenderParams, ModelInParamsConflictsWithALocalObj) {
  TempDir dir;
  const fs::path file = dir.write("p.json", R"({"model":"0123456789abcdef"})");
  const Options o = parse({"render", "spot.obj", "--params", file.string(), "-o", "x.png"});
  EXPECT_TRUE(contains(usage_error([&] { build_render_params(o, schema()); }), "drop one"));
}

// proto/examples/ are requests people copy; each must pass the schema and
// work as a --params file.
TEST(RenderParams, ProtoExamplesAreValidRequests) {
  const fs::path examples = fs::path(__FILE__).parent_path() / "../../proto/examples";
  if (!fs::is_directory(examples)) GTEST_SKIP() << "no source tree at " << examples;
  int count = 0;
  for (const auto& entry : fs::directory_iterator(examples)) {
    if (entry.path().extension() != ".json") continue;
    ++count;
    const Options o = parse({"render", "--params", entry.path().string(), "-o", "x.png"});
    EXPECT_EQ(usage_error([&] { build_render_params(o, schema()); }), "") << entry.path();
  }
  EXPECT_GE(count, 2);
}

// ---------------------------------------------------------------- bundle discovery

std::vector<std::string> names(const BundleScan& scan) {
  std::vector<std::string> out;
  for (const BundleFile& f : scan.files) out.push_back(f.name);
  return out;
}

bool has_warning(const BundleScan& scan, const std::string& needle) {
  return std::any_of(scan.warnings.begin(), scan.warnings.end(),
                     [&](const std::string& w) { return contains(w, needle); });
}

TEST(BundleScan, FindsMtlAndTexturesWithSubfoldersBackslashesAndCase) {
  TempDir dir;
  const fs::path root = dir.path() / "model";
  dir.write("model/model.obj", "# comment\r\nmtllib model.mtl\r\nmtllib missing.mtl\r\nv 0 0 0\r\nf 1 1 1\r\n");
  dir.write("model/model.mtl",
            "newmtl a\n"
            "Kd 1 1 1\n"
            "map_Kd Textures\\Color.PNG\n"          // backslash and wrong case
            "map_Bump -bm 2 sub/normal.png\n"       // option before the name
            "map_Ns -imfchan r spec.png -bm 1.5\n"  // option after the name
            "bump texture 01.png\n"                 // unescaped space
            "  map_d ../secret.png\n"               // leaves the folder
            "map_Ks /etc/passwd\n"                  // absolute
            "norm nothere.png\n"                    // missing
            "newmtl b\n"
            "map_kd textures/color.png\n"  // same file again, other keyword case
            "map_Ka ambient.png\n");       // not a texture toond uses
  dir.write("model/textures/color.png", "colour");
  dir.write("model/sub/normal.png", "normal");
  dir.write("model/spec.png", "spec");
  dir.write("model/texture 01.png", "spaced");
  dir.write("model/ambient.png", "ambient");
  dir.write("secret.png", "must never be sent");

  const BundleScan scan = scan_obj_bundle(root / "model.obj");
  EXPECT_EQ(names(scan), (std::vector<std::string>{"model.obj", "model.mtl", "textures/color.png", "sub/normal.png",
                                                   "spec.png", "texture 01.png"}));
  EXPECT_EQ(scan.files[2].content, "colour");
  EXPECT_TRUE(has_warning(scan, "missing.mtl"));
  EXPECT_TRUE(has_warning(scan, "'../secret.png' refused"));
  EXPECT_TRUE(has_warning(scan, "'/etc/passwd' refused"));
  EXPECT_TRUE(has_warning(scan, "nothere.png"));
  for (const BundleFile& f : scan.files) {
    EXPECT_NE(f.content, "must never be sent") << f.name;
  }
}

TEST(BundleScan, TexturesResolveRelativeToTheirMtlInsideTheFolder) {
  TempDir dir;
  dir.write("m.obj", "mtllib ./folder/sub.mtl\n");
  dir.write("folder/sub.mtl", "map_Kd image.jpg\nmap_Bump ../top.png\nmap_d ../../out.png\n");
  dir.write("folder/image.jpg", "jpg");
  dir.write("top.png", "top");
  const BundleScan scan = scan_obj_bundle(dir.path() / "m.obj");
  EXPECT_EQ(names(scan), (std::vector<std::string>{"m.obj", "folder/sub.mtl", "folder/image.jpg", "top.png"}));
  EXPECT_TRUE(has_warning(scan, "'../../out.png' refused"));
}

TEST(BundleScan, GltfBringsTheFilesItsUrisNameAndAFolderItsModelFile) {
  TempDir dir;
  dir.write("model/scene.gltf",
            R"({"asset": {"version": "2.0"}, "buffers": [{"uri": "scene.bin", "byteLength": 4}],
                "images": [{"uri": "tex/my%20skin.png"}, {"uri": "data:image/png;base64,AAAA"},
                           {"uri": "../secret.png"}]})");
  dir.write("model/scene.bin", "bin!");
  dir.write("model/tex/my skin.png", "png");
  dir.write("model/unrelated.png", "not named");
  dir.write("secret.png", "must never be sent");
  const BundleScan scan = scan_obj_bundle(dir.path() / "model");
  // A folder also sends the images beside its model, named or not.
  EXPECT_EQ(names(scan), (std::vector<std::string>{"scene.gltf", "scene.bin", "tex/my skin.png", "unrelated.png"}));
  EXPECT_TRUE(has_warning(scan, "'../secret.png' refused"));
  EXPECT_EQ(names(scan_obj_bundle(dir.path() / "model" / "scene.gltf")),
            (std::vector<std::string>{"scene.gltf", "scene.bin", "tex/my skin.png"}));

  dir.write("glb/only.glb", std::string("glTF\x02\0\0\0", 8));
  EXPECT_EQ(names(scan_obj_bundle(dir.path() / "glb" / "only.glb")), (std::vector<std::string>{"only.glb"}));
  // Several model files travel together: the daemon tells a model from the
  // files holding its clips alone.
  dir.write("two/a.obj", "");
  dir.write("two/b.glb", "");
  EXPECT_EQ(names(scan_obj_bundle(dir.path() / "two")), (std::vector<std::string>{"a.obj", "b.glb"}));
  EXPECT_THROW(scan_obj_bundle(dir.path() / "glb" / "none"), UsageError);
}

// A game's model names no skin (its game's code sets it): a folder sends
// the images and the clip files beside it.
TEST(BundleScan, AFolderSendsTheImagesAndClipFilesBesideItsModel) {
  TempDir dir;
  dir.write("player/character.b3d", "b3d");
  dir.write("player/character.png", "skin");
  dir.write("player/notes.txt", "not sent");
  dir.write("flag/ffflag.md5mesh", "mesh");
  dir.write("flag/ffflag.md5anim", "anim");
  dir.write("flag/ffflag_cc.png", "skin");
  dir.write("flag/lower_default.skin", "skin file");
  EXPECT_EQ(names(scan_obj_bundle(dir.path() / "player")),
            (std::vector<std::string>{"character.b3d", "character.png"}));
  EXPECT_EQ(names(scan_obj_bundle(dir.path() / "flag")),
            (std::vector<std::string>{"ffflag.md5anim", "ffflag.md5mesh", "ffflag_cc.png", "lower_default.skin"}));
}

// An FBX or COLLADA file names its textures by whatever path the artist's
// machine had; toon sends what the daemon will find: the path as written
// inside the folder, else the file name beside the model.
TEST(BundleScan, AnFbxOrColladaFileBringsTheImagesItNames) {
  TempDir dir;
  const std::string fbx = std::string("Kaydara FBX Binary  \0\x1a\0", 23) + "S\x1b\0\0\0" +
                          "C:\\Users\\me\\maps\\Skin.PNG" + std::string("\0\x05", 2) + "S\x0e\0\0\0" +
                          "textures/eyes.jpg" + "\x01" + std::string("RelativeFilename\0", 17) + "gone.tga";
  dir.write("hero/hero.fbx", fbx);
  dir.write("hero/skin.png", "skin");
  dir.write("hero/textures/eyes.jpg", "eyes");
  dir.write("hero/unrelated.png", "not named");
  const BundleScan scan = scan_obj_bundle(dir.path() / "hero" / "hero.fbx");
  EXPECT_EQ(names(scan), (std::vector<std::string>{"hero.fbx", "skin.png", "textures/eyes.jpg"}));
  EXPECT_TRUE(has_warning(scan, "'gone.tga' not found"));

  dir.write("scene/scene.dae",
            "<library_images><image id=\"a\"><init_from>../../etc/secret.png</init_from></image>"
            "<image id=\"b\"><init_from>paint.png</init_from></image></library_images>");
  dir.write("scene/paint.png", "paint");
  dir.write("etc/secret.png", "must never be sent");
  const BundleScan collada = scan_obj_bundle(dir.path() / "scene" / "scene.dae");
  // The file name alone is looked up beside the model, where there is none.
  EXPECT_EQ(names(collada), (std::vector<std::string>{"scene.dae", "paint.png"}));
}

TEST(BundleScan, MtllibWithSeveralNamesAndEscapedSpaces) {
  TempDir dir;
  dir.write("m.obj", "mtllib gone.mtl my\\ file.mtl\nmtllib two words.mtl\n");
  dir.write("my file.mtl", "newmtl x\n");
  dir.write("two words.mtl", "newmtl y\n");
  const BundleScan scan = scan_obj_bundle(dir.path() / "m.obj");
  EXPECT_EQ(names(scan), (std::vector<std::string>{"m.obj", "my file.mtl", "two words.mtl"}));
  EXPECT_TRUE(has_warning(scan, "gone.mtl"));
}

TEST(BundleScan, SymlinkLeadingOutsideIsRefused) {
  TempDir dir;
  dir.write("outside/secret.png", "secret");
  dir.write("model/m.obj", "mtllib m.mtl\n");
  dir.write("model/m.mtl", "map_Kd link.png\n");
  std::error_code ec;
  fs::create_symlink(dir.path() / "outside/secret.png", dir.path() / "model/link.png", ec);
  if (ec) GTEST_SKIP() << "cannot create symlinks here: " << ec.message();
  const BundleScan scan = scan_obj_bundle(dir.path() / "model/m.obj");
  EXPECT_EQ(names(scan), (std::vector<std::string>{"m.obj", "m.mtl"}));
  EXPECT_TRUE(has_warning(scan, "link.png"));
}

TEST(BundleScan, MissingObjIsAUsageError) {
  TempDir dir;
  EXPECT_TRUE(contains(usage_error([&] { scan_obj_bundle(dir.path() / "none.obj"); }), "none.obj"));
  EXPECT_FALSE(usage_error([&] { scan_obj_bundle(dir.path()); }).empty());
}

// The scan of an OBJ whose one library, m.mtl, holds `mtl`.
BundleScan scan_with_library(const TempDir& dir, const std::string& mtl) {
  dir.write("m.obj", "mtllib m.mtl\n");
  dir.write("m.mtl", mtl);
  return scan_obj_bundle(dir.path() / "m.obj");
}

TEST(BundleScan, OtherCaseIsMatchedOverTheWholePathAsTheDaemonDoes) {
  TempDir dir;
  // "tex" exists as written but holds only "A.png"; of the spellings of
  // "tex/a.png" on disk, the daemon's rule picks the least, "Tex/a.png", so
  // that is the one file both statements need.
  dir.write("tex/A.png", "lower folder");
  dir.write("Tex/a.png", "upper folder");
  const BundleScan scan = scan_with_library(dir, "newmtl a\nmap_Kd tex/a.png\nnewmtl b\nmap_Kd Tex/a.png\n");
  EXPECT_EQ(names(scan), (std::vector<std::string>{"m.obj", "m.mtl", "Tex/a.png"}));
  EXPECT_TRUE(scan.warnings.empty());
}

TEST(BundleScan, ForeignAbsolutePathsFallBackToTheFileNameBesideTheMtl) {
  TempDir dir;
  dir.write("skin.png", "png");
  const BundleScan scan = scan_with_library(dir, "newmtl a\nmap_Kd C:\\Users\\artist\\skin.png\nmap_Ks /etc/passwd\n");
  EXPECT_EQ(names(scan), (std::vector<std::string>{"m.obj", "m.mtl", "skin.png"}));
  EXPECT_TRUE(has_warning(scan, "'/etc/passwd' refused: absolute path"));
}

TEST(BundleScan, TextureKeywords) {
  EXPECT_TRUE(is_texture_keyword("map_bump"));
  EXPECT_TRUE(is_texture_keyword("norm"));
  EXPECT_FALSE(is_texture_keyword("map_Ka"));
  EXPECT_FALSE(is_texture_keyword("newmtl"));
}

TEST(BundleScan, SharedModelsResolveCompletely) {
  TOOND_REQUIRE_SHARED_MODELS();
  const fs::path models = test::shared_models_dir();

  const BundleScan dog = scan_obj_bundle(models / "kenney-cube-pet-dog/animal-dog.obj");
  EXPECT_EQ(names(dog), (std::vector<std::string>{"animal-dog.obj", "animal-dog.mtl", "Textures/colormap.png"}));
  EXPECT_TRUE(dog.warnings.empty());

  const BundleScan windmill = scan_obj_bundle(models / "windmill/windmill.obj");
  EXPECT_EQ(windmill.files.size(), 7u);  // obj, mtl, 2 diffuse, 2 normal maps, 1 specular
  EXPECT_TRUE(windmill.warnings.empty());

  // Missing references upstream are warnings, never errors.
  const BundleScan options = scan_obj_bundle(models / "edge-cases/tinyobjloader/texture-options-issue-85.obj");
  EXPECT_GE(options.files.size(), 2u);
  EXPECT_FALSE(options.warnings.empty());
}

// ---------------------------------------------------------------- replies

TEST(Reply, ToondErrorBodyBecomesOneLine) {
  EXPECT_EQ(describe_error_reply(
                400, R"({"error":{"code":"invalid_parameter","message":"too wide","path":"/outline/width"}})", ""),
            "error 400 invalid_parameter at /outline/width: too wide");
  EXPECT_EQ(describe_error_reply(404, R"({"error":{"code":"unknown_model","message":"no such model","path":""}})", ""),
            "error 404 unknown_model: no such model");
  EXPECT_EQ(describe_error_reply(503, R"({"error":{"code":"busy","message":"queue full"}})", "2"),
            "error 503 busy: queue full (busy; retry after 2 s)");
}

TEST(Reply, ForeignBodiesAreSummarised) {
  EXPECT_EQ(describe_error_reply(502, "<html>Bad Gateway</html>\n<body>...", ""),
            "error 502: <html>Bad Gateway</html>");
  EXPECT_EQ(describe_error_reply(500, "", ""), "error 500 (empty answer)");
  EXPECT_EQ(describe_error_reply(502, " \tBad Gateway \r\nmore", ""), "error 502: Bad Gateway");
}

TEST(Reply, PngSizeAndHelpers) {
  std::string png("\x89PNG\r\n\x1a\n\0\0\0\x0dIHDR\0\0\x02\0\0\0\x01\x80", 24);
  const auto size = png_size(png);
  ASSERT_TRUE(size.has_value());
  EXPECT_EQ(size->first, 512u);
  EXPECT_EQ(size->second, 384u);
  EXPECT_FALSE(png_size("GIF89a....................").has_value());
  EXPECT_EQ(content_type_for("Textures/a.JPG"), "image/jpeg");
  EXPECT_EQ(content_type_for("spot.obj"), "text/plain");
  EXPECT_EQ(human_bytes(1500000), "1.5 MB");
}

// -o picks the sheet's file by its extension; anything else is the image.
TEST(RenderAnswer, TheExtensionOfOutPicksTheSheetsFile) {
  EXPECT_EQ(render_answer_for("walk.aseprite").query, "?atlas=aseprite");
  EXPECT_EQ(render_answer_for("out/WALK.ASE").query, "?atlas=aseprite");
  EXPECT_EQ(render_answer_for("walk.json").query, "?atlas=json");
  const RenderAnswer godot = render_answer_for("sprites/walk cycle.tres");
  EXPECT_EQ(godot.query, "?atlas=godot&texture=walk%20cycle.png") << "the PNG beside it, by name";
  EXPECT_EQ(godot.companion_png, "sprites/walk cycle.png");
  // The image as it comes: output svg (which a .svg name asks for) answers an SVG.
  for (const char* image : {"walk.png", "turn.webp", "lines.svg", "-", "noext"}) {
    const RenderAnswer answer = render_answer_for(image);
    EXPECT_EQ(answer.query, "") << image;
    EXPECT_EQ(answer.companion_png, "") << image;
    EXPECT_EQ(answer.content_types, (std::vector<std::string>{"image/png", "image/webp", "image/svg+xml"})) << image;
  }
  EXPECT_EQ(percent_encoded("a b/ü"), "a%20b%2F%C3%BC");
}

}  // namespace
}  // namespace toond::cli
