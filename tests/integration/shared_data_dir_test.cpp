// Replicas behind a load balancer share one data directory: whatever one
// stores or removes, the others see at once, loading models lazily.
#include <gtest/gtest.h>

#include "support/generated_models.h"
#include "test_client.h"

namespace toond::test {
namespace {

bool listed(httplib::Client& client, const std::string& id) {
  auto res = client.Get("/models");
  if (!res || res->status != 200) {
    ADD_FAILURE() << "GET /models failed";
    return false;
  }
  const auto body = nlohmann::json::parse(res->body);
  for (const auto& m : body["models"]) {
    if (m["id"] == id) return true;
  }
  return false;
}

TEST(SharedDataDir, AModelUploadedThroughOneReplicaIsListedAndRenderedByAnotherStartedBefore) {
  const auto dir = make_temp_dir("toond-shared");
  {
    Daemon a(dir);
    Daemon b(dir);  // running before the upload, so it cannot have read it at start
    auto ca = a.client();
    auto cb = b.client();
    const std::string id = upload_obj_text(ca, sphere_obj(24, 12), "ball.obj");
    ASSERT_FALSE(id.empty());

    EXPECT_TRUE(listed(cb, id));
    auto described = cb.Get(("/models/" + id).c_str());
    ASSERT_TRUE(described);
    EXPECT_EQ(described->status, 200);
    const nlohmann::json params = {{"width", 64}, {"height", 64}};
    auto on_a = post_json(ca, "/models/" + id + "/render", params);
    auto on_b = post_json(cb, "/models/" + id + "/render", params);
    ASSERT_TRUE(on_a && on_b);
    ASSERT_EQ(on_b->status, 200) << on_b->body;
    EXPECT_EQ(on_a->body, on_b->body);

    // Deleted through A: B, which has it in memory and on its GPU, stops
    // rendering it too.
    ASSERT_EQ(ca.Delete(("/models/" + id).c_str())->status, 200);
    EXPECT_FALSE(listed(cb, id));
    auto gone = post_json(cb, "/models/" + id + "/render", params);
    ASSERT_TRUE(gone);
    EXPECT_EQ(gone->status, 404);
    EXPECT_EQ(error_of(gone)["code"], "unknown_model");

    // Uploaded again through B: A renders it again.
    EXPECT_EQ(upload_obj_text(cb, sphere_obj(24, 12), "ball.obj"), id);
    auto back = post_json(ca, "/models/" + id + "/render", params);
    ASSERT_TRUE(back);
    EXPECT_EQ(back->status, 200);
    EXPECT_EQ(back->body, on_a->body);
  }
  std::filesystem::remove_all(dir);
}

}  // namespace
}  // namespace toond::test
