// ShaderCache (compiler/driver/ShaderCache.h): a batch's workers compile each shader code once,
// a failed compile is not kept, a group of codes compiles once for all, and a compile through
// compileShader is the same module with or without the cache.

#include <gtest/gtest.h>

#include <atomic>
#include <chrono>
#include <map>
#include <stdexcept>
#include <thread>

#include "compiler/driver/Compiler.h"
#include "compiler/driver/ShaderCache.h"
#include "support/TestSupport.h"

namespace mxc::test {
namespace {

using Words = ShaderCache::Words;

// A cache holds at most its capacity of keys and modules: past it the least recently used code
// is dropped, and compiled again when a later material has it. Here each entry is a one-letter
// key and 1,000 words (4,001 bytes), and the capacity holds two.
TEST(ShaderCache, DropsTheLeastRecentlyUsedCodesPastItsCapacity) {
  ShaderCache cache(2 * 4001);
  std::map<std::string, int> compiles;
  auto get = [&](const std::string& key) {
    return cache.getOrCompile(key, [&]() -> std::optional<Words> {
      ++compiles[key];
      return Words(1000, uint32_t(key[0]));
    });
  };
  EXPECT_EQ(get("a"), Words(1000, uint32_t('a')));
  get("b");
  EXPECT_EQ(cache.heldBytes(), 2u * 4001u);
  get("a");  // a hit: "a" is now the most recently used, "b" the least
  EXPECT_EQ(cache.hits(), 1u);
  get("c");  // past the capacity: "b" goes
  EXPECT_EQ(cache.evicted(), 1u);
  EXPECT_EQ(cache.heldBytes(), 2u * 4001u);
  EXPECT_EQ(get("a"), Words(1000, uint32_t('a')));
  EXPECT_EQ(compiles["a"], 1);  // kept
  EXPECT_EQ(get("b"), Words(1000, uint32_t('b')));
  EXPECT_EQ(compiles["b"], 2);  // dropped, so compiled again (and "c" goes)
  EXPECT_EQ(cache.evicted(), 2u);
  EXPECT_EQ(compiles["c"], 1);
  // One entry larger than the capacity is kept until the next one comes.
  ShaderCache small(100);
  EXPECT_EQ(small.getOrCompile("big", [] { return std::optional<Words>(Words(1000, 7u)); }), Words(1000, 7u));
  EXPECT_EQ(small.heldBytes(), 4003u);
  small.getOrCompile("next", [] { return std::optional<Words>(Words(10, 1u)); });
  EXPECT_EQ(small.evicted(), 1u);
  EXPECT_EQ(small.heldBytes(), 44u);
}

// Group compiles count against the capacity too; a member whose module was dropped before its
// material came compiles alone, with the same words.
TEST(ShaderCache, AGroupMemberDroppedBeforeItsMaterialCameCompilesAlone) {
  ShaderCache cache(2 * 4001);
  cache.addGroup({"a", "b", "c"}, [] {
    std::map<std::string, Words> made;
    for (const char* key : {"a", "b", "c"}) made[key] = Words(1000, uint32_t(key[0]));
    return made;
  });
  int alone = 0;
  auto compileAlone = [&](char key) {
    return [&alone, key]() -> std::optional<Words> {
      ++alone;
      return Words(1000, uint32_t(key));
    };
  };
  ShaderCache::Served served{};
  EXPECT_EQ(cache.getOrCompile("c", compileAlone('c'), &served), Words(1000, uint32_t('c')));
  EXPECT_EQ(served, ShaderCache::Served::CutFromGroup);
  EXPECT_EQ(cache.grouped(), 3u);
  EXPECT_EQ(cache.evicted(), 1u);  // "a", the first made
  EXPECT_EQ(cache.getOrCompile("a", compileAlone('a'), &served), Words(1000, uint32_t('a')));
  EXPECT_EQ(served, ShaderCache::Served::Compiled);
  EXPECT_EQ(alone, 1);
}

TEST(ShaderCache, CompilesEachCodeOnceForEveryWorker) {
  ShaderCache cache;
  std::atomic<int> compiles{0};
  auto compile = [&]() -> std::optional<Words> {
    ++compiles;
    std::this_thread::sleep_for(std::chrono::milliseconds(30));  // the others arrive meanwhile
    return Words{0x07230203u, 42u};
  };
  std::vector<std::optional<Words>> got(4);
  std::vector<std::thread> workers;
  for (size_t i = 0; i < got.size(); ++i) workers.emplace_back([&, i] { got[i] = cache.getOrCompile("code", compile); });
  for (std::thread& t : workers) t.join();
  EXPECT_EQ(compiles.load(), 1);
  EXPECT_EQ(cache.hits(), 3u);
  for (const auto& words : got) EXPECT_EQ(words, (Words{0x07230203u, 42u}));
  // Another code is compiled for itself.
  EXPECT_EQ(cache.getOrCompile("other", [] { return std::optional<Words>(Words{1u}); }), Words{1u});
  EXPECT_EQ(cache.hits(), 3u);
}

TEST(ShaderCache, AFailedCompileIsNotKept) {
  ShaderCache cache;
  int compiles = 0;
  EXPECT_FALSE(cache.getOrCompile("code", [&] {
    ++compiles;
    return std::optional<Words>();
  }));
  // The next material with that code compiles it itself (its errors name its own document).
  EXPECT_EQ(cache.getOrCompile("code", [&] {
    ++compiles;
    return std::optional<Words>(Words{7u});
  }), Words{7u});
  EXPECT_EQ(compiles, 2);
  EXPECT_EQ(cache.hits(), 0u);
}

// A worker waiting on another's compile that fails (returns nothing, or throws) takes the
// compile over, with the cache unlocked: its compile can use the cache (a locked one would
// hang here), and its words are kept.
void waiterCompilesAfterTheOwnerFails(bool owner_throws) {
  ShaderCache cache;
  std::atomic<bool> started{false}, release{false};
  std::thread owner([&] {
    auto failing = [&]() -> std::optional<Words> {
      started = true;
      while (!release) std::this_thread::yield();
      if (owner_throws) throw std::runtime_error("out of memory");
      return std::nullopt;
    };
    if (owner_throws) {
      EXPECT_THROW(cache.getOrCompile("code", failing), std::runtime_error);
    } else {
      EXPECT_FALSE(cache.getOrCompile("code", failing));
    }
  });
  while (!started) std::this_thread::yield();
  std::optional<Words> second;
  std::thread waiter([&] {
    second = cache.getOrCompile("code", [&] {
      EXPECT_EQ(cache.getOrCompile("inner", [] { return std::optional<Words>(Words{3u}); }), Words{3u});
      return std::optional<Words>(Words{9u});
    });
  });
  std::this_thread::sleep_for(std::chrono::milliseconds(50));  // the waiter is now waiting
  release = true;
  owner.join();
  waiter.join();
  EXPECT_EQ(second, Words{9u});
  EXPECT_EQ(cache.hits(), 0u);
  // Its words are kept: the next worker takes them.
  EXPECT_EQ(cache.getOrCompile("code", [] { return std::optional<Words>(); }), Words{9u});
}

TEST(ShaderCache, AWorkerWaitingOnAFailedCompileCompilesItself) { waiterCompilesAfterTheOwnerFails(false); }

TEST(ShaderCache, AWorkerWaitingOnACompileThatThrowsCompilesItself) { waiterCompilesAfterTheOwnerFails(true); }

// A group (driver/ShaderGroups.h) compiles once for all its keys, at the first request of any;
// a key it did not make, or every key of a group that throws, compiles alone.
TEST(ShaderCache, AGroupCompilesOnceForAllItsKeys) {
  ShaderCache cache;
  int groupCompiles = 0;
  cache.addGroup({"a", "b", "c"}, [&] {
    ++groupCompiles;
    return std::map<std::string, Words>{{"a", Words{1u}}, {"b", Words{2u}}};  // c: not made
  });
  auto never = []() -> std::optional<Words> {
    ADD_FAILURE() << "a key the group made compiled alone";
    return std::nullopt;
  };
  ShaderCache::Served served = ShaderCache::Served::Compiled;
  EXPECT_EQ(cache.getOrCompile("b", never, &served), Words{2u});
  EXPECT_EQ(served, ShaderCache::Served::CutFromGroup);
  EXPECT_EQ(cache.getOrCompile("a", never), Words{1u});
  int alone = 0;
  EXPECT_EQ(cache.getOrCompile("c", [&] {
    ++alone;
    return std::optional<Words>(Words{3u});
  }, &served), Words{3u});
  EXPECT_EQ(served, ShaderCache::Served::Compiled);
  EXPECT_EQ(groupCompiles, 1);
  EXPECT_EQ(alone, 1);
  EXPECT_EQ(cache.grouped(), 2u);
  EXPECT_EQ(cache.hits(), 0u);  // each module went to the material it was made for
  EXPECT_EQ(cache.getOrCompile("a", never, &served), Words{1u});
  EXPECT_EQ(served, ShaderCache::Served::SameCode);
  EXPECT_EQ(cache.hits(), 1u);  // another material of a's code
}

TEST(ShaderCache, AGroupThatThrowsLeavesEachKeyToCompileAlone) {
  ShaderCache cache;
  cache.addGroup({"a", "b"}, []() -> std::map<std::string, Words> { throw std::runtime_error("glslang"); });
  EXPECT_TRUE(cache.compileAGroup());
  EXPECT_FALSE(cache.compileAGroup());
  EXPECT_EQ(cache.getOrCompile("a", [] { return std::optional<Words>(Words{5u}); }), Words{5u});
  EXPECT_EQ(cache.getOrCompile("b", [] { return std::optional<Words>(Words{6u}); }), Words{6u});
  EXPECT_EQ(cache.grouped(), 0u);
}

TEST(ShaderCache, CompileAGroupTakesTheLargestFirstAndKeysAreInOneGroup) {
  ShaderCache cache;
  std::vector<std::string> order;
  auto group = [&](std::string name, std::vector<std::string> keys) {
    return [&order, name, keys] {
      order.push_back(name);
      std::map<std::string, Words> made;
      for (const std::string& k : keys) made[k] = Words{uint32_t(k.size())};
      return made;
    };
  };
  cache.addGroup({"a", "b"}, group("small", {"a", "b"}));
  cache.addGroup({"c", "d", "e"}, group("large", {"c", "d", "e"}));
  // A key already in a group stays in it; a group left with one key is no group.
  cache.addGroup({"a", "f"}, group("taken", {"a", "f"}));
  EXPECT_TRUE(cache.compileAGroup());
  EXPECT_TRUE(cache.compileAGroup());
  EXPECT_FALSE(cache.compileAGroup());
  EXPECT_EQ(order, (std::vector<std::string>{"large", "small"}));
  EXPECT_EQ(cache.grouped(), 5u);
}

// Through the compiler's entry point: the second material of the same code takes the first's
// module, which is the module compiled without the cache.
TEST(ShaderCache, CompileShaderSharesTheModuleOfTheSameCode) {
  auto document = [](const std::string& name) {
    return mtlx("  <open_pbr_surface name=\"s\" type=\"surfaceshader\">\n"
                "    <input name=\"base_color\" type=\"color3\" value=\"0.2, 0.5, 0.3\" />\n"
                "  </open_pbr_surface>\n  <surfacematerial name=\"" + name +
                "\" type=\"material\"><input name=\"surfaceshader\" type=\"surfaceshader\" nodename=\"s\" />"
                "</surfacematerial>\n");
  };
  Context context;
  ShaderCache cache;
  std::vector<std::vector<uint32_t>> modules;
  for (const std::string name : {"Green", "Also_green"}) {
    CompileRequest request;
    request.document = name + ".mtlx";
    request.text = document(name);
    request.shaderCache = &cache;
    Compiler compiler(context, std::move(request));
    ASSERT_EQ(compiler.materials().size(), 1u) << context.diagnostics.format();
    auto words = compiler.spirv(compiler.shader(compiler.materials()[0]));
    ASSERT_TRUE(words) << context.diagnostics.format();
    modules.push_back(*words);
  }
  EXPECT_EQ(cache.hits(), 1u);
  EXPECT_EQ(modules[0], modules[1]);
  CompileRequest alone;
  alone.document = "Green.mtlx";
  alone.text = document("Green");
  Compiler compiler(context, std::move(alone));
  ASSERT_EQ(compiler.materials().size(), 1u);
  EXPECT_EQ(compiler.spirv(compiler.shader(compiler.materials()[0])), modules[0]);
}

}  // namespace
}  // namespace mxc::test
