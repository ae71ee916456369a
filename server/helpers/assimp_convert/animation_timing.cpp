#include "helpers/assimp_convert/animation_timing.h"

#include <algorithm>
#include <cmath>
#include <cstdio>

namespace toond::assimp_convert {
namespace {

// The clip's name as the glTF writer gives it, which is what the daemon
// lists.
std::string written_name(const aiAnimation& clip) {
  return clip.mName.length > 0 ? std::string(clip.mName.C_Str()) : std::string("anim");
}

std::string number(double value) {
  char text[32];
  std::snprintf(text, sizeof text, "%g", value);
  return text;
}

template <typename Key>
void see_keys(const Key* keys, unsigned count, double& last) {
  if (!keys) return;
  for (unsigned k = 0; k < count; ++k) last = std::max(last, keys[k].mTime);
}

// Tracks of one key are left out: assimp gives a channel without keys of
// some kind one key of that kind at time 0, the node's rest transform.
template <typename Key>
void see_first_keys(const Key* keys, unsigned count, double& first) {
  if (!keys || count < 2) return;
  for (unsigned k = 0; k < count; ++k) first = std::min(first, keys[k].mTime);
}

// One frame earlier; a lone key at 0 stays there.
template <typename Key>
void one_frame_earlier(Key* keys, unsigned count) {
  for (unsigned k = 0; k < count; ++k) keys[k].mTime = std::max(0.0, keys[k].mTime - 1.0);
}

// The latest key time of the clip; -infinity without keys.
double last_key(const aiAnimation& clip) {
  double last = -INFINITY;
  for (unsigned c = 0; clip.mChannels && c < clip.mNumChannels; ++c) {
    const aiNodeAnim* channel = clip.mChannels[c];
    if (!channel) continue;
    see_keys(channel->mPositionKeys, channel->mNumPositionKeys, last);
    see_keys(channel->mRotationKeys, channel->mNumRotationKeys, last);
    see_keys(channel->mScalingKeys, channel->mNumScalingKeys, last);
  }
  for (unsigned c = 0; clip.mMorphMeshChannels && c < clip.mNumMorphMeshChannels; ++c) {
    const aiMeshMorphAnim* channel = clip.mMorphMeshChannels[c];
    if (channel) see_keys(channel->mKeys, channel->mNumKeys, last);
  }
  return last;
}

double first_key(const aiAnimation& clip) {
  double first = INFINITY;
  for (unsigned c = 0; c < clip.mNumChannels; ++c) {
    const aiNodeAnim& channel = *clip.mChannels[c];
    see_first_keys(channel.mPositionKeys, channel.mNumPositionKeys, first);
    see_first_keys(channel.mRotationKeys, channel.mNumRotationKeys, first);
    see_first_keys(channel.mScalingKeys, channel.mNumScalingKeys, first);
  }
  for (unsigned c = 0; c < clip.mNumMorphMeshChannels; ++c) {
    see_first_keys(clip.mMorphMeshChannels[c]->mKeys, clip.mMorphMeshChannels[c]->mNumKeys, first);
  }
  return first;
}

// Assimp's validation allows this much past the duration before it refuses.
constexpr double kValidationSlack = 0.001;

}  // namespace

bool timing_refusal(const std::string& validation_error) {
  return validation_error.find("is larger than aiAnimation::mDuration") != std::string::npos ||
         validation_error.find("aiAnimation::mNumChannels is 0") != std::string::npos;
}

std::vector<std::string> lengthen_clips_to_their_keys(aiScene& scene) {
  std::vector<std::string> said;
  if (!scene.mAnimations) return said;
  unsigned kept = 0;
  for (unsigned a = 0; a < scene.mNumAnimations; ++a) {
    aiAnimation* clip = scene.mAnimations[a];
    if (!clip) {
      scene.mAnimations[kept++] = clip;  // left for the validation to refuse
      continue;
    }
    if (clip->mNumChannels == 0 && clip->mNumMorphMeshChannels == 0) {
      said.push_back("clip '" + written_name(*clip) + "' animates nothing and is left out");
      delete clip;
      continue;
    }
    const double last = last_key(*clip);
    if (clip->mDuration > 0.0 && last > clip->mDuration + kValidationSlack) {
      said.push_back("clip '" + written_name(*clip) + "' has keys up to " + number(last) + " ticks, past the " +
                     number(clip->mDuration) + " its file states: it runs to its last key");
      clip->mDuration = last;
    }
    scene.mAnimations[kept++] = clip;
  }
  scene.mNumAnimations = kept;
  if (kept == 0) {
    delete[] scene.mAnimations;
    scene.mAnimations = nullptr;
  }
  return said;
}

std::vector<std::string> count_b3d_frames_from_zero(aiScene& scene) {
  std::vector<std::string> said;
  for (unsigned a = 0; a < scene.mNumAnimations; ++a) {
    aiAnimation& clip = *scene.mAnimations[a];
    if (!(first_key(clip) >= 1.0)) continue;
    for (unsigned c = 0; c < clip.mNumChannels; ++c) {
      aiNodeAnim& channel = *clip.mChannels[c];
      one_frame_earlier(channel.mPositionKeys, channel.mNumPositionKeys);
      one_frame_earlier(channel.mRotationKeys, channel.mNumRotationKeys);
      one_frame_earlier(channel.mScalingKeys, channel.mNumScalingKeys);
    }
    for (unsigned c = 0; c < clip.mNumMorphMeshChannels; ++c) {
      one_frame_earlier(clip.mMorphMeshChannels[c]->mKeys, clip.mMorphMeshChannels[c]->mNumKeys);
    }
    clip.mDuration = std::max(0.0, clip.mDuration - 1.0);
    said.push_back("clip '" + written_name(clip) + "': B3D frames count from 1; frame 1 is taken as time 0");
  }
  return said;
}

std::vector<std::string> give_clips_a_speed(aiScene& scene) {
  std::vector<std::string> said;
  for (unsigned a = 0; a < scene.mNumAnimations; ++a) {
    aiAnimation& clip = *scene.mAnimations[a];
    if (std::isfinite(clip.mTicksPerSecond) && clip.mTicksPerSecond > 0.0) continue;
    clip.mTicksPerSecond = 1.0;
    said.push_back("clip '" + written_name(clip) + "' states no speed: it plays one key tick a second");
  }
  return said;
}

std::vector<std::string> frame_rate_lines(const aiScene& scene, const std::string& format) {
  std::vector<std::string> lines;
  if (format != "b3d" && format != "fbx" && format != "ms3d" && format != "md5anim" && format != "bvh") return lines;
  for (unsigned a = 0; a < scene.mNumAnimations; ++a) {
    const double rate = scene.mAnimations[a]->mTicksPerSecond;
    if (std::isfinite(rate) && rate > 0.0) lines.push_back("frame_rate: " + std::to_string(a) + " " + number(rate));
  }
  return lines;
}

}  // namespace toond::assimp_convert
