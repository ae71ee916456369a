#include "cli_flags.h"

#include <algorithm>
#include <cstdlib>

namespace toond::cli {
namespace {

using Value = const std::string&;

int parse_size(const std::string& text) {
  const bool digits = is_index(text) && text.size() <= 5;
  const long value = digits ? std::strtol(text.c_str(), nullptr, 10) : 0;
  if (!digits || value < 16 || value > 4096) {
    throw UsageError("--size '" + text + "': expected a whole number of pixels from 16 to 4096");
  }
  return static_cast<int>(value);
}

std::vector<std::string> split_names(const std::string& text) {
  std::vector<std::string> names;
  std::size_t start = 0;
  while (start <= text.size()) {
    const std::size_t comma = std::min(text.find(',', start), text.size());
    std::string name = text.substr(start, comma - start);
    if (name.empty() || name == "." || name == ".." || name.find('/') != std::string::npos) {
      throw UsageError("--only '" + text + "': expected model folder names separated by commas");
    }
    names.push_back(std::move(name));
    start = comma + 1;
  }
  return names;
}

// `v` itself, which must not be empty: `complaint` otherwise.
const std::string& required(Value v, const char* complaint) {
  if (v.empty()) throw UsageError(complaint);
  return v;
}

void set_output(FlagTarget& t, Value v) {
  t.options.output = required(v, "-o needs a file name (or - for standard output)");
}

// --output names the layer (the schema's `output`, checked with the other
// parameters); a file name there is the old spelling of -o.
void set_output_layer(FlagTarget& t, Value v) {
  if (v.empty() || v == "-" || v.find_first_of("./") != std::string::npos) {
    throw UsageError("--output '" + v + "': --output names the layer (color, lines, depth, normal, id or svg); " +
                     "the file is -o FILE or --out FILE");
  }
  t.options.sets.emplace_back("output", v);
}

constexpr VerbSet kUpload = verb_set(Verb::upload);
constexpr VerbSet kRender = verb_set(Verb::render);
constexpr VerbSet kGallery = verb_set(Verb::gallery);

const Flag kFlags[] = {
    {{"", "--server", "URL", "toond's address (default: $TOOND_URL, else\nhttp://127.0.0.1:8080)"},
     kGlobal,
     false,
     [](FlagTarget& t, Value v) { t.server = v; }},
    {{"-h", "--help", "", "show this help"}, kGlobal, true, [](FlagTarget& t, Value) { t.options.help = true; }},
    {{"", "--version", "", "print toon's version"},
     kGlobal,
     true,
     [](FlagTarget& t, Value) { t.options.version = true; }},

    {{"-q", "--quiet", "", "print only the model id"},
     kUpload,
     true,
     [](FlagTarget& t, Value) { t.options.quiet = true; }},
    {{"", "--scene", "N", "glTF: draw scene N instead of the file's default"},
     kUpload,
     false,
     [](FlagTarget& t, Value v) {
       if (!is_index(v) || v.size() > 9) throw UsageError("--scene '" + v + "': expected a scene's index, 0 or more");
       t.options.scene = v;
     }},
    {{"", "--smooth-angle", "D",
      "for files without normals: faces meeting at more than D\ndegrees keep their own normals (0..180, default 30)"},
     kUpload,
     false,
     [](FlagTarget& t, Value v) {
       char* end = nullptr;
       const double d = std::strtod(v.c_str(), &end);
       if (v.empty() || end != v.c_str() + v.size() || !(d >= 0 && d <= 180)) {
         throw UsageError("--smooth-angle '" + v + "': expected degrees from 0 to 180");
       }
       t.options.smooth_angle = v;
     }},
    {{"", "--up", "y|z", "the file's up axis (default: the format's, z for STL, PLY, 3MF, AMF, IQM)"},
     kUpload,
     false,
     [](FlagTarget& t, Value v) {
       if (v != "y" && v != "z") throw UsageError("--up '" + v + "': expected y or z");
       t.options.up = v;
     }},

    {{"", "--textures", "A.png,B.png",
      "put these images of the upload on the materials, in\nmaterial order or as MATERIAL:IMAGE, as a game sets\na "
      "model's skins"},
     kUpload,
     false,
     [](FlagTarget& t, Value v) { t.options.textures = required(v, "--textures needs a list of images"); }},

    {{"", "--model", "ID", "render a model stored earlier with `toon upload`"},
     kRender,
     false,
     [](FlagTarget& t, Value v) { t.options.model_id = required(v, "--model needs a model id"); }},
    {{"", "--params", "FILE.json", "start from this JSON of render parameters (- reads stdin)"},
     kRender,
     false,
     [](FlagTarget& t, Value v) { t.options.params_file = required(v, "--params needs a file name"); }},
    {{"", "--set", "key.sub=value",
      "set one parameter, checked against the schema before\n"
      "anything is sent; may be repeated, later ones win.\n"
      "Lists are comma-separated or JSON, objects JSON:\n"
      "  --set outline.width=3 --set shading.steps=4\n"
      "  --set background=1,1,1 --set lights.0.intensity=1.5\n"
      "  --set outline.method=hull,edges --set sheet.animation.clip=walk"},
     kRender,
     true,
     [](FlagTarget& t, Value v) {
       const std::size_t eq = v.find('=');
       if (eq == std::string::npos || eq == 0) {
         throw UsageError("--set '" + v + "': expected key.sub=value, e.g. --set outline.width=3");
       }
       t.options.sets.emplace_back(v.substr(0, eq), v.substr(eq + 1));
     }},
    {{"", "--output", "LAYER",
      "the layer to render: color (default), lines, depth,\n"
      "normal, id or svg; the same as --set output=LAYER"},
     kRender,
     false,
     set_output_layer},
    {{"-o", "--out", "FILE",
      "where to write the answer: a PNG, an animated WebP\n"
      "for sheet.animate, an SVG for output svg (a name ending\n"
      ".svg asks for it); a sheet's .aseprite file (.aseprite,\n"
      ".ase), Godot SpriteFrames (.tres, its PNG beside it) or\n"
      "atlas (.json) by the extension (required; - for stdout)"},
     kRender,
     false,
     set_output},

    {{"", "--models", "DIR", "the folder of model folders (default: ../shared/models)"},
     kGallery,
     false,
     [](FlagTarget& t, Value v) { t.options.models_dir = required(v, "--models needs a folder"); }},
    {{"", "--all", "",
      "every model folder in DIR, then bob.glb (default:\n"
      "spot, kenney-cube-pet-dog, kenney-space-craft,\n"
      "windmill, stanford-bunny, utah-teapot, bob.glb)"},
     kGallery,
     true,
     [](FlagTarget& t, Value) { t.options.all_models = true; }},
    {{"", "--only", "NAME[,NAME]", "just these model folders, in this order; may be repeated"},
     kGallery,
     true,
     [](FlagTarget& t, Value v) {
       for (std::string& name : split_names(v)) t.options.only.push_back(std::move(name));
     }},
    {{"", "--size", "N", "width and height of each render in pixels (default 256)"},
     kGallery,
     false,
     [](FlagTarget& t, Value v) { t.options.size = parse_size(v); }},
    {{"-o", "--out", "DIR", "the folder to write (created if missing; required)"}, kGallery, false, set_output},
};

const VerbInfo kVerbs[] = {
    {Verb::health, "health", "", "show the daemon's status and the OpenGL renderer it uses",
     R"(Asks the daemon for GET /healthz and prints its answer: status and the
OpenGL vendor, renderer and version it renders with.
Exit status 0 when the status is "ok", 1 otherwise or when it cannot be reached.
)"},
    {Verb::upload, "upload",
     "PATH.obj|PATH.glb|PATH.gltf|PATH.stl|PATH.ply|PATH.fbx|PATH.dae|...|FOLDER [-q]\n"
     "[--scene N] [--smooth-angle D] [--up y|z] [--textures A.png,B.png]",
     "store a model with its textures (OBJ + MTL, glTF, STL, PLY, FBX,\nCOLLADA, 3DS, ...); prints the model id",
     R"(Sends an OBJ model to the daemon's store (POST /models) together with the
MTL files its mtllib lines name and the textures those MTL files reference
(map_Kd, map_Ks, map_Ns, map_d, map_Bump, bump, norm, disp). Files are sent
with their path relative to the OBJ's folder; references that leave that
folder are refused, missing files are reported and skipped. A .m mesh
(`Vertex i x y z {normal=(...)}` / `Face i a b c` lines) and a .glb are
sent alone, and so are .stl and .ply files; a .gltf brings the .bin and image
files its URIs name (inside its folder). An FBX, COLLADA (.dae), 3DS, 3MF,
OFF or other file the daemon reads through assimp brings the images it
names, found as written or by file name beside it. A folder sends its model
files (.obj, .gltf, .glb, .stl, .ply, .iqm, .fbx, .dae, .3ds, .3mf, .off,
.b3d, .md3, .md5mesh, .m or another format assimp reads) with what they
name, and every image and .skin file beside them: a game model's skin, and
the files holding its clips alone (.md5anim, an IQM of poses, a BVH, an
animation-only FBX or glTF), whose clips the daemon adds to the model.
--textures A.png,B.png puts those images on the model's materials in
material order (or MATERIAL:IMAGE by name), as a game's code sets them.
A glTF file's default scene is drawn; --scene N picks another (another model,
with its own id). In a file without normals, faces meeting at more than 30
degrees keep their own normals and shallower edges are smoothed (normals by
angle, as Blender's Auto Smooth; OBJ smoothing groups decide where the file
has them; glTF without normals is flat, as its specification says):
--smooth-angle D changes the angle, and --up y|z says which of the file's
axes is up (default: the format's convention, z for STL, PLY, 3MF, AMF and
IQM, y for the rest). Each is part of the model's id.
Prints the daemon's answer (id, triangles, materials, textures, warnings).
)"},
    {Verb::info, "info", "ID", "show what the daemon knows of a stored model, its animation clips too",
     R"(Asks the daemon for GET /models/ID and prints its answer: triangles,
materials, textures, files, the import's warnings and, for a model that
moves, its animation clips (name, duration in seconds, channels, and frame_rate
where the format keys by frame) with its
joint and morph-target counts. A clip is rendered with
--set animation.clip=NAME --set animation.time=SECONDS, a part of it
with --set animation.range=START,END (see toon render --help).
)"},
    {Verb::render, "render",
     "[PATH.obj|PATH.m | --model ID] [--params FILE.json]\n[--set key.sub=value ...] -o "
     "OUT.png|OUT.webp|OUT.svg|OUT.aseprite|OUT.tres|OUT.json",
     "render a PNG of a local OBJ, a stored model or the demo model",
     R"(Renders a PNG (POST /render), or an animated WebP when the parameters ask
for sheet.animate. With PATH.obj (or a .m, .gltf or .glb model) the model and
its MTL files and textures are uploaded with the request; with --model a stored model is used;
with neither the daemon's built-in demo model renders.
A sheet (--set sheet.frames=8, sheet.animation.clip=Walk) goes to engines
as the extension of -o says: walk.aseprite (?atlas=aseprite: one .aseprite
file for Aseprite, Unity, Bevy, LOVE, MonoGame), walk.tres (?atlas=godot: a
Godot 4 SpriteFrames resource, and walk.png beside it, which it names),
walk.json (?atlas=json: the atlas alone); --set sheet.pack=true trims and
packs the tiles; --set sheet.layers=color,lines draws each frame as the
colour without its lines and the lines alone (a layer each in the
.aseprite file; packed alike).
A clip's range (animation.range, sheet.animation.range) is two numbers,
seconds on the file's time base (--set sheet.animation.range=5.6,6.23),
or frames where the clip has a frame rate (toon info lists it): with
--model ID, --set sheet.animation.range=168f,187f is frames 168 to 187.
)"},
    {Verb::gallery, "gallery", "[--models DIR] [--all | --only NAME[,NAME...]]\n[--size N] -o OUTDIR",
     "render every preset and effect on a folder of models into PNGs,\na contact sheet and an HTML index",
     R"(Renders every preset the daemon offers (GET /presets) and one look per
effect (specular, rim, halftone, contours, shadows, two-tone, a colour ramp,
outline colours, antialiasing, coloured and point lights, the lines layer and
an 8-direction sprite sheet) on each model, and
writes OUTDIR/<model>/<look>.png, OUTDIR/contact-sheet.png (rows are models,
columns are looks) and OUTDIR/index.html, which shows every image with its
exact parameters and the `toon render` command that repeats it.
A model is a folder of DIR with exactly one .obj directly inside; its MTL
files and textures are found as `toon upload` finds them. NAME.glb stands
for folder NAME's model sent as a .glb that toon writes from its OBJ (kept
as OUTDIR/NAME.glb/<obj name>.glb), so glTF is shown too. Progress goes to
stderr. A failed render is reported and the rest still run and are written;
the exit status is then 1.
)"},
};

}  // namespace

bool is_index(std::string_view s) { return !s.empty() && s.find_first_not_of("0123456789") == std::string_view::npos; }

std::span<const Flag> flags() { return kFlags; }

std::string flag_display(const text::OptionHelp& flag) {
  return flag.alias.empty() ? std::string(flag.name) : std::string(flag.alias) + "/" + std::string(flag.name);
}

std::span<const VerbInfo> verbs() { return kVerbs; }

}  // namespace toond::cli
