// The small-block pool of GMP (gmp_small_block_pool.h), in an executable of its own: it
// replaces GMP's memory functions for the whole process.

#include <CGAL/Triangular_spline/gmp_small_block_pool.h>

#include <gmpxx.h>
#include <gtest/gtest.h>

#include <cstring>
#include <random>
#include <thread>
#include <vector>

namespace TS = CGAL::Triangular_spline;
namespace TSI = CGAL::Triangular_spline::internal;

namespace {

// sum_{k=1}^{n} 1/(k(k+1)) = n/(n+1), and the partial sums' products with a fraction that
// grows past four limbs and shrinks back: every class and the malloc() path are crossed.
void telescoping(unsigned first, unsigned n, std::vector<mpq_class>& kept) {
  mpq_class sum = 0;
  for (unsigned k = first; k < first + n; ++k) {
    sum += mpq_class(1, (unsigned long)k * (k + 1));
    if (k % 7 == 0)
      kept.push_back(sum); // freed later, by another thread
  }
  mpq_class expected(mpz_class(n), mpz_class(first) * (first + n));
  expected.canonicalize();
  EXPECT_EQ(sum, expected);
  mpz_class big = 1;
  for (int i = 0; i < 40; ++i)
    big *= mpz_class("18446744073709551557"); // 40 limbs
  mpq_class q(big, big + 1);
  q *= mpq_class(big + 1, big);
  EXPECT_EQ(q, 1);
}

} // namespace

TEST(GmpPool, InstallsOnceAndServesEveryClass) {
  // allocated by malloc() before the pool: freed into it afterwards
  std::vector<mpz_class> before;
  for (int i = 0; i < 100; ++i)
    before.emplace_back(mpz_class(1) << (64 * (i % 4) + 1));
  if constexpr (!TSI::gmp_pool_supported)
    GTEST_SKIP() << "no pool under AddressSanitizer";
  ASSERT_TRUE(TS::use_gmp_small_block_pool());
  ASSERT_TRUE(TS::use_gmp_small_block_pool()); // idempotent
  void* (*allocate)(std::size_t);
  mp_get_memory_functions(&allocate, nullptr, nullptr);
  EXPECT_EQ(allocate, &TSI::gmp_pool_allocate);
  before.clear();
  // the four classes and what goes to malloc()
  EXPECT_EQ(TSI::gmp_pool_class(8), 0u);
  EXPECT_EQ(TSI::gmp_pool_class(32), 3u);
  EXPECT_EQ(TSI::gmp_pool_class(40), TSI::gmp_pool_classes);
  EXPECT_EQ(TSI::gmp_pool_class(12), TSI::gmp_pool_classes); // strings
  EXPECT_EQ(TSI::gmp_pool_class(0), TSI::gmp_pool_classes);
  std::vector<mpq_class> kept;
  telescoping(1, 5000, kept);
  // strings of any length through malloc() and GMP's free function
  for (const char* digits : {"7", "123456789012345678901234567890", "-42"}) {
    const mpz_class z(digits);
    char* s = mpz_get_str(nullptr, 10, z.get_mpz_t());
    EXPECT_STREQ(s, digits);
    void (*release)(void*, std::size_t);
    mp_get_memory_functions(nullptr, nullptr, &release);
    release(s, std::strlen(s) + 1);
  }
}

TEST(GmpPool, BlocksMoveBetweenThreadsAndOutliveThem) {
  if constexpr (!TSI::gmp_pool_supported)
    GTEST_SKIP() << "no pool under AddressSanitizer";
  ASSERT_TRUE(TS::use_gmp_small_block_pool());
  // Each round: four threads compute and keep values; the next round's threads free the
  // previous round's values (blocks carved by ended threads) while computing their own.
  std::vector<std::vector<mpq_class>> kept(4);
  for (int round = 0; round < 6; ++round) {
    std::vector<std::vector<mpq_class>> next(4);
    std::vector<std::thread> threads;
    for (unsigned t = 0; t < 4; ++t)
      threads.emplace_back([&, t] {
        kept[t].clear();
        telescoping(1 + 1000 * t + 7 * unsigned(round), 3000, next[t]);
      });
    for (std::thread& thread : threads)
      thread.join();
    kept = std::move(next);
  }
  // Lists of ended threads were handed over, and are used again: the values a fresh thread
  // computes are still right, and the shared lists or slabs hold blocks.
  std::size_t handed = 0;
  {
    const std::lock_guard<std::mutex> lock(TSI::gmp_pool_shared().mutex);
    for (const auto& lists : TSI::gmp_pool_shared().lists)
      for (const auto& list : lists)
        handed += list.count;
    handed += TSI::gmp_pool_shared().slabs.size();
  }
  EXPECT_GT(handed, 0u);
  for (const auto& values : kept)
    for (std::size_t i = 1; i < values.size(); ++i)
      EXPECT_LT(values[i - 1], values[i]); // partial sums increase
  std::thread([&] {
    std::vector<mpq_class> mine;
    telescoping(3, 20000, mine);
  }).join();
}

TEST(GmpPool, ReallocationKeepsTheDigits) {
  if constexpr (!TSI::gmp_pool_supported)
    GTEST_SKIP() << "no pool under AddressSanitizer";
  ASSERT_TRUE(TS::use_gmp_small_block_pool());
  std::mt19937_64 random(7);
  for (int i = 0; i < 200; ++i) {
    mpz_class z = mpz_class(std::to_string(random() | 1));
    const int limbs = 1 + int(random() % 12);
    mpz_class expected = z;
    mpz_realloc2(z.get_mpz_t(), mp_bitcnt_t(64 * limbs)); // grows or keeps (one limb stays)
    EXPECT_EQ(z, expected);
    z <<= 64 * (limbs - 1); // several limbs, then back to one
    z >>= 64 * (limbs - 1);
    mpz_realloc2(z.get_mpz_t(), 64);
    EXPECT_EQ(z, expected);
  }
}
