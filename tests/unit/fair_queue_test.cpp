#include <gtest/gtest.h>

#include <algorithm>
#include <string>
#include <vector>

#include "render/run/fair_queue.h"

namespace toond::render {
namespace {

std::vector<std::string> drain(FairQueue<std::string>& q) {
  std::vector<std::string> order;
  while (!q.empty()) order.push_back(q.pop());
  return order;
}

TEST(FairQueue, ABurstDoesNotPushAnotherClientToTheBack) {
  FairQueue<std::string> q;
  for (int i = 0; i < 100; ++i) q.push("a", "a" + std::to_string(i));
  q.push("b", "b0");
  EXPECT_EQ(q.size(), 101u);
  const std::vector<std::string> order = drain(q);
  // b's one request comes second, after a's first, not 101st.
  ASSERT_EQ(order.size(), 101u);
  EXPECT_EQ(order[0], "a0");
  EXPECT_EQ(order[1], "b0");
  EXPECT_EQ(order[2], "a1");
  EXPECT_EQ(order.back(), "a99");
}

TEST(FairQueue, ClientsTakeTurnsAndEachKeepsItsOwnOrder) {
  FairQueue<std::string> q;
  q.push("a", "a0");
  q.push("a", "a1");
  q.push("b", "b0");
  q.push("c", "c0");
  q.push("b", "b1");
  EXPECT_EQ(drain(q), (std::vector<std::string>{"a0", "b0", "c0", "a1", "b1"}));
}

TEST(FairQueue, AClientThatComesBackWaitsForTheRoundInProgress) {
  FairQueue<std::string> q;
  q.push("a", "a0");
  q.push("b", "b0");
  EXPECT_EQ(q.pop(), "a0");
  q.push("a", "a1");  // a's line was empty: it joins behind b
  EXPECT_EQ(drain(q), (std::vector<std::string>{"b0", "a1"}));
}

TEST(FairQueue, TakeAllEmptiesIt) {
  FairQueue<std::string> q;
  q.push("a", "a0");
  q.push("b", "b0");
  std::vector<std::string> all = q.take_all();
  std::sort(all.begin(), all.end());
  EXPECT_EQ(all, (std::vector<std::string>{"a0", "b0"}));
  EXPECT_TRUE(q.empty());
  EXPECT_EQ(q.size(), 0u);
  q.push("c", "c0");
  EXPECT_EQ(q.pop(), "c0");
}

}  // namespace
}  // namespace toond::render
