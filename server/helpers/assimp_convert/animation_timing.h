#pragma once
// When a file's clips run, as the daemon is told it: keys in seconds (the
// glTF answer's), each clip's frame rate where the format keys by frame,
// and the harmless slips of real exporters mended on the way instead of
// losing the whole file. Minetest's own player model (B3D) keys frame 221
// of a clip its ANIM chunk says is 220 frames long, which assimp's
// validation step refuses; its writer counts frames from 1, as its reader
// (Irrlicht, Minetest's engine) takes them.
#include <string>
#include <vector>

#include <assimp/scene.h>

namespace toond::assimp_convert {

// Whether assimp's validation refused the scene only for what
// lengthen_clips_to_their_keys mends: a key past its clip's stated
// duration, or a clip without any channel.
bool timing_refusal(const std::string& validation_error);

// Clips whose keys run past their stated duration take the last key as
// their end; clips without any channel are dropped. One sentence per clip
// mended. The scene is not validated yet: only animations are touched, and
// their pointers checked before they are read.
std::vector<std::string> lengthen_clips_to_their_keys(aiScene& scene);

// B3D keys count frames from 1 (frame 1 is the first pose): shifted so that
// the first frame is at time 0, as Irrlicht and the file's Blender source
// number them; only when no key lies before frame 1 (a track of one key,
// which assimp adds at 0 where a channel keys no rotation or scale, stays).
std::vector<std::string> count_b3d_frames_from_zero(aiScene& scene);

// A clip that states no speed (ticks per second 0 or not a number) plays
// one tick a second, with a sentence; the glTF writer would divide by it.
std::vector<std::string> give_clips_a_speed(aiScene& scene);

// "frame_rate: INDEX FPS" for each clip whose ticks are the file's frames
// (B3D, FBX, MilkShape 3D, MD5 and BVH animations): what the daemon reports as the clip's
// frame_rate. Other formats' ticks are not frames (COLLADA's are
// milliseconds, ASE's a fraction of a frame) and get no line.
std::vector<std::string> frame_rate_lines(const aiScene& scene, const std::string& format);

}  // namespace toond::assimp_convert
