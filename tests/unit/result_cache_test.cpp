// The result cache's bookkeeping and ETag matching, without a daemon.
#include <gtest/gtest.h>

#include "http/render_answer.h"
#include "pipeline/result_cache.h"

namespace toond::pipeline {
namespace {

std::shared_ptr<const CachedRender> png_of(std::size_t bytes, char fill = 'x') {
  auto r = std::make_shared<CachedRender>();
  r->body.assign(bytes, fill);
  r->etag = etag_of(r->body);
  return r;
}

TEST(ResultCache, EvictsLeastRecentlyUsedToStayWithinItsBytes) {
  ResultCache cache(3000);
  cache.put("a", png_of(1000, 'a'));
  cache.put("b", png_of(1000, 'b'));
  ASSERT_TRUE(cache.find("a"));  // a is now the most recent
  cache.put("c", png_of(1000, 'c'));
  EXPECT_LE(cache.bytes(), 3000u);
  EXPECT_TRUE(cache.find("a"));
  EXPECT_FALSE(cache.find("b")) << "least recently used goes first";
  EXPECT_TRUE(cache.find("c"));
  EXPECT_EQ(cache.entries(), 2u);
}

TEST(ResultCache, KeepsNothingLargerThanItselfAndNothingAtZero) {
  ResultCache small(500);
  small.put("big", png_of(1000));
  EXPECT_FALSE(small.find("big"));
  EXPECT_EQ(small.bytes(), 0u);
  ResultCache off(0);
  off.put("a", png_of(1));
  EXPECT_FALSE(off.find("a"));
}

TEST(ResultCache, ReplacingAKeyDoesNotCountItTwice) {
  ResultCache cache(10000);
  cache.put("a", png_of(1000));
  const std::size_t once = cache.bytes();
  cache.put("a", png_of(1000, 'y'));
  EXPECT_EQ(cache.bytes(), once);
  EXPECT_EQ(cache.find("a")->body[0], 'y');
  EXPECT_EQ(cache.hits(), 1u);
}

TEST(ETag, IsAQuotedHashOfTheBytes) {
  EXPECT_EQ(etag_of("abc"), etag_of("abc"));
  EXPECT_NE(etag_of("abc"), etag_of("abd"));
  const std::string tag = etag_of("abc");
  EXPECT_EQ(tag.size(), 18u);
  EXPECT_EQ(tag.front(), '"');
  EXPECT_EQ(tag.back(), '"');
}

TEST(ETag, IfNoneMatchListsWeakTagsAndStar) {
  using http::etag_matches;
  const std::string tag = etag_of("png");
  EXPECT_TRUE(etag_matches(tag, tag));
  EXPECT_TRUE(etag_matches("*", tag));
  EXPECT_TRUE(etag_matches("\"1\", " + tag, tag));
  EXPECT_TRUE(etag_matches("W/" + tag, tag));
  EXPECT_FALSE(etag_matches("\"1\", \"2\"", tag));
  EXPECT_FALSE(etag_matches("", tag));
  EXPECT_FALSE(etag_matches(tag.substr(1), tag)) << "an unquoted tag is a different tag";
}

}  // namespace
}  // namespace toond::pipeline
