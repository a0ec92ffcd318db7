// Tests of the input/output layer: exact number parsing, scattered .xyz data and its
// Delaunay domain, triangle meshes read through CGAL IO, constrained domains with holes,
// the embedded demo data set, and the tspline-spline file format. Every rejection path is
// checked together with the content of its message.

#include "test_support.h"

#include <CGAL/Triangular_spline/Domain/constrained_domain.h>
#include <CGAL/Triangular_spline/Domain/demo_data.h>
#include <CGAL/Triangular_spline/IO/mesh_io.h>
#include <CGAL/Triangular_spline/IO/npy.h>
#include <CGAL/Triangular_spline/IO/number_parsing.h>
#include <CGAL/Triangular_spline/IO/scattered_data.h>
#include <CGAL/Triangular_spline/IO/spline_file.h>
#include <CGAL/Triangular_spline/internal/parallel.h>

#include <CGAL/Gmpq.h>
#include <CGAL/Polygon_2_algorithms.h>

#include <algorithm>
#include <atomic>
#include <chrono>
#include <cstdint>
#include <cmath>
#include <cstring>
#include <filesystem>
#include <fstream>
#include <functional>
#include <initializer_list>
#include <limits>
#include <numeric>
#include <random>
#include <sstream>
#include <string>
#include <vector>

using namespace ts_test;
using TS::Invalid_input;
using Exact_FT = Exact_kernel::FT;

namespace {

// Runs `f`, which must throw Invalid_input whose message contains every string of `parts`.
::testing::AssertionResult throws_with(const std::function<void()>& f,
                                       std::initializer_list<std::string> parts) {
  try {
    f();
  } catch (const Invalid_input& e) {
    const std::string message = e.what();
    for (const std::string& part : parts)
      if (message.find(part) == std::string::npos)
        return ::testing::AssertionFailure()
               << "message \"" << message << "\" lacks \"" << part << "\"";
    return ::testing::AssertionSuccess();
  } catch (const std::exception& e) {
    return ::testing::AssertionFailure() << "wrong exception type: " << e.what();
  }
  return ::testing::AssertionFailure() << "no exception";
}

// A fresh directory under the system temporary directory, removed at the end of the test.
class Temporary_directory {
public:
  Temporary_directory() {
    static std::atomic<int> counter{0};
    const auto stamp = std::chrono::steady_clock::now().time_since_epoch().count();
    m_path = std::filesystem::temp_directory_path() /
             ("tspline_test_io_" + std::to_string(stamp) + "_" + std::to_string(counter++));
    std::filesystem::create_directories(m_path);
  }
  ~Temporary_directory() {
    std::error_code ignored;
    std::filesystem::remove_all(m_path, ignored);
  }
  std::string write(const std::string& name, const std::string& contents) const {
    const std::filesystem::path file = m_path / name;
    std::ofstream(file) << contents;
    return file.string();
  }
  std::string path(const std::string& name) const { return (m_path / name).string(); }

private:
  std::filesystem::path m_path;
};

template <class K>
typename K::FT ratio(int p, int q) {
  return typename K::FT(p) / typename K::FT(q);
}

// A callable that reads `text` as a spline file named "s.spline" (for throws_with()).
template <class K>
std::function<void()> spline_reading(const std::string& text) {
  return [text] {
    std::istringstream in(text);
    CGAL::Triangular_spline::read_spline_file<K>(in, "s.spline");
  };
}

} // namespace

// ---------------------------------------------------------------------------------------
// Numbers
// ---------------------------------------------------------------------------------------

TEST(NumberParsing, ExactDecimalsAreExact) {
  EXPECT_EQ(TS::parse_number<Exact_FT>("0.1"), Exact_FT(1) / Exact_FT(10));
  EXPECT_EQ(TS::parse_number<Exact_FT>("1e-3"), Exact_FT(1) / Exact_FT(1000));
  EXPECT_EQ(TS::parse_number<Exact_FT>("-2.5e2"), Exact_FT(-250));
  EXPECT_EQ(TS::parse_number<Exact_FT>("+.5"), Exact_FT(1) / Exact_FT(2));
  EXPECT_EQ(TS::parse_number<Exact_FT>("5."), Exact_FT(5));
  EXPECT_EQ(TS::parse_number<Exact_FT>("0012.50E+1"), Exact_FT(125));
  EXPECT_EQ(TS::parse_number<Exact_FT>("-0.000"), Exact_FT(0));
  EXPECT_EQ(TS::parse_number<Exact_FT>("0e99999999999999"), Exact_FT(0));
  EXPECT_EQ(TS::parse_number<Exact_FT>("3/4"), Exact_FT(3) / Exact_FT(4));
  EXPECT_EQ(TS::parse_number<Exact_FT>("-14/4"), Exact_FT(-7) / Exact_FT(2));
  EXPECT_EQ(TS::parse_number<Exact_FT>("123456789012345678901234567890"),
            TS::parse_number<Exact_FT>("1234567890123456789012345678.9e2"));
  // 0.1 is not a double: the exact value differs from the double's.
  EXPECT_NE(TS::parse_number<Exact_FT>("0.1"), Exact_FT(0.1));
  // The largest accepted magnitude, and the nearest to zero.
  EXPECT_EQ(TS::parse_number<Exact_FT>("1e150"), TS::internal::power_of_ten<Exact_FT>(150));
  EXPECT_EQ(TS::parse_number<Exact_FT>("-1e150"), -TS::internal::power_of_ten<Exact_FT>(150));
  EXPECT_GT(TS::parse_number<Exact_FT>("4.9406564584124654e-324"), Exact_FT(0));
}

// GMP rationals are parsed in GMP directly (digits, a power of ten, one gcd): random decimal
// tokens give the value of the generic rational arithmetic (CGAL::Gmpq), in canonical form.
TEST(NumberParsing, GmpDecimalsAreTheGenericRationals) {
  static_assert(std::is_same_v<Exact_FT, mpq_class>);
  std::mt19937 random(17);
  for (int n = 0; n < 3000; ++n) {
    std::string token = random() % 2 ? "-" : "";
    const int before = int(random() % 25), after = int(random() % 25);
    for (int i = 0; i < before; ++i)
      token += char('0' + random() % 10);
    if (after > 0 || before == 0)
      token += '.';
    for (int i = 0; i < after || (before == 0 && i == 0); ++i)
      token += char('0' + random() % 10);
    if (random() % 3 == 0)
      token += "e" + std::to_string(int(random() % 121) - 60);
    const Exact_FT fast = TS::parse_number<Exact_FT>(token);
    const CGAL::Gmpq generic = TS::parse_number<CGAL::Gmpq>(token);
    const mpq_class expected(generic.mpq());
    EXPECT_TRUE(mpq_equal(fast.get_mpq_t(), expected.get_mpq_t())) << token;
    mpz_class g;
    mpz_gcd(g.get_mpz_t(), fast.get_num_mpz_t(), fast.get_den_mpz_t());
    EXPECT_EQ(g, 1) << token;
  }
}

TEST(NumberParsing, DoublesUseStrtod) {
  EXPECT_EQ(TS::parse_number<double>("0.1"), 0.1);
  EXPECT_EQ(TS::parse_number<double>("1e-3"), 1e-3);
  EXPECT_EQ(TS::parse_number<double>("-2.5e2"), -250.0);
  EXPECT_EQ(TS::parse_number<double>("1e150"), 1e150);
  EXPECT_EQ(TS::parse_number<double>(".5"), 0.5);
}

TEST(NumberParsing, RejectionsQuoteTheToken) {
  for (const bool exact : {false, true}) {
    auto parse = [exact](const std::string& token) {
      return [exact, token] {
        if (exact)
          TS::parse_number<Exact_FT>(token);
        else
          TS::parse_number<double>(token);
      };
    };
    SCOPED_TRACE(exact ? "exact" : "double");
    EXPECT_TRUE(throws_with(parse(""), {"empty"}));
    for (const char* token : {"nan", "NaN", "-nan", "inf", "-Inf", "infinity"})
      EXPECT_TRUE(throws_with(parse(token), {"\"" + std::string(token) + "\"", "not finite"}));
    for (const std::string& token : {std::string("1e200"), std::string("-1e151"),
                                     std::string("1.0000000000000001e151"), std::string("2e150")})
      EXPECT_TRUE(throws_with(parse(token), {"\"" + token + "\"", "too large"}));
    for (const char* token : {"abc", "1.2.3", "1e", "1e+", "e5", ".", "-", "1,5", "0x10", "1 2",
                              "12abc", "--1", "1e5.0", "1/"})
      EXPECT_TRUE(throws_with(parse(token), {"\"" + std::string(token) + "\""}));
    EXPECT_TRUE(throws_with(parse("1e-500"), {"\"1e-500\"", "too close to zero"}));
  }
  // Fractions: exact only, with a positive denominator.
  EXPECT_TRUE(
      throws_with([] { TS::parse_number<double>("1/3"); }, {"\"1/3\"", "not a decimal number"}));
  EXPECT_TRUE(throws_with([] { TS::parse_number<Exact_FT>("1/0"); }, {"\"1/0\"", "zero"}));
  EXPECT_TRUE(throws_with([] { TS::parse_number<Exact_FT>("1/-3"); }, {"\"1/-3\""}));
  EXPECT_TRUE(throws_with([] { TS::parse_number<Exact_FT>("0.5/3"); }, {"\"0.5/3\""}));
  EXPECT_TRUE(throws_with([] { TS::parse_number<Exact_FT>("-3" + std::string(150, '0') + "/2"); },
                          {"too large"}));
  EXPECT_EQ(TS::parse_number<Exact_FT>("-2" + std::string(150, '0') + "/2"),
            -TS::internal::power_of_ten<Exact_FT>(150));
  EXPECT_TRUE(throws_with([] { TS::parse_number<Exact_FT>("2" + std::string(150, '0') + "/0001"); },
                          {"too large"}));
  EXPECT_EQ(TS::parse_number<Exact_FT>("0003/0004"), Exact_FT(3) / Exact_FT(4));
}

TEST(NumberParsing, LongTokensAreQuotedShort) {
  // Issue 13: a 10^6-digit token was echoed in full, a 1 MB error line.
  for (const std::size_t digits : {std::size_t(156), std::size_t(1000000)}) {
    const std::string token = "1" + std::string(digits - 1, '0');
    for (const bool exact : {false, true}) {
      try {
        if (exact)
          TS::parse_number<Exact_FT>(token);
        else
          TS::parse_number<double>(token);
        ADD_FAILURE() << "no exception";
      } catch (const Invalid_input& e) {
        const std::string message = e.what();
        EXPECT_LT(message.size(), 120u) << message.substr(0, 200);
        EXPECT_NE(message.find("\"1" + std::string(39, '0') + "...\" (" + std::to_string(digits) +
                               " characters)"),
                  std::string::npos)
            << message.substr(0, 200);
        EXPECT_NE(message.find("too large"), std::string::npos);
      }
    }
  }
  // Up to 40 characters a token is quoted whole.
  const std::string forty = "1" + std::string(39, 'x');
  EXPECT_TRUE(throws_with([&] { TS::parse_number<double>(forty); }, {"\"" + forty + "\" is not"}));
}

TEST(TextTokens, EveryBlankSeparatesTokens) {
  using V = std::vector<std::string>;
  EXPECT_EQ(TS::internal::split_tokens(""), V());
  for (const char* blank : {" ", "\t", "\r", "\f", "\v", "\r\r", " \t\r\f\v"}) {
    SCOPED_TRACE(::testing::PrintToString(std::string(blank)));
    EXPECT_EQ(TS::internal::split_tokens(blank), V());
    EXPECT_EQ(TS::internal::tokens_of_line(blank), V());
    const std::string b = blank;
    EXPECT_EQ(TS::internal::split_tokens(b + "a" + b + "bc" + b), (V{"a", "bc"}));
    EXPECT_EQ(TS::internal::tokens_of_line("a" + b + "b#" + b + "c"), (V{"a", "b"}));
  }
}

TEST(NumberParsing, FormatRoundTrips) {
  EXPECT_EQ(TS::format_number<Exact_FT>(Exact_FT(1) / Exact_FT(3)), "1/3");
  EXPECT_EQ(TS::format_number<Exact_FT>(Exact_FT(-10) / Exact_FT(4)), "-5/2");
  EXPECT_EQ(TS::format_number(Exact_FT(7)), "7");
  EXPECT_EQ(TS::format_number(Exact_FT(0)), "0");
  // the shortest decimals that read back to the same double
  EXPECT_EQ(TS::format_number(0.1), "0.1");
  EXPECT_EQ(TS::format_number(1.0 / 3.0), "0.3333333333333333");
  EXPECT_EQ(TS::format_number(-2.5e-300), "-2.5e-300");
  EXPECT_EQ(TS::format_number(std::nextafter(1.0, 2.0)), "1.0000000000000002");
  Random_rationals random(7);
  for (int i = 0; i < 200; ++i) {
    const Exact_FT q = random.rational<Exact_FT>(1000000, 999983);
    EXPECT_EQ(TS::parse_number<Exact_FT>(TS::format_number(q)), q);
    const double d = random.rational<double>(1000000, 999983);
    EXPECT_EQ(TS::parse_number<double>(TS::format_number(d)), d);
  }
  EXPECT_EQ(TS::parse_number<double>(TS::format_number(5e-324)), 5e-324);
}

TEST(NumberParsing, GmpRationalsAreWrittenAsTheGenericFractions) {
  // GMP's C++ rationals are written straight from their parts; CGAL::Gmpq goes through
  // Fraction_traits and a string stream. Both give the same text, for numbers of many limbs
  // and every sign.
  static_assert(TS::internal::Is_gmpxx_rational<mpq_class>::value);
  static_assert(!TS::internal::Is_gmpxx_rational<CGAL::Gmpq>::value);
  static_assert(!TS::internal::Is_gmpxx_rational<double>::value);
  Random_rationals random(11);
  for (int i = 0; i < 300; ++i) {
    mpq_class q = random.rational<mpq_class>(1000000007, 999983);
    for (int k = 0; k < i % 7; ++k)
      q *= random.rational<mpq_class>(2147483647, 2147483629) + mpq_class(1, 3);
    if (i % 3 == 0)
      q = -q;
    if (i % 50 == 0)
      q = i % 100 == 0 ? mpq_class(0) : mpq_class(-123456789);
    const std::string text = TS::format_number(q);
    EXPECT_EQ(text, TS::format_number(CGAL::Gmpq(q.get_mpq_t()))) << i;
    EXPECT_EQ(TS::parse_number<mpq_class>(text), q) << text;
  }
  mpq_class third(-7, 21), three(12, 4); // as constructed, not reduced
  EXPECT_EQ(TS::format_number(three), TS::format_number(CGAL::Gmpq(three.get_mpq_t())));
  third.canonicalize(); // arithmetic keeps them reduced
  three.canonicalize();
  EXPECT_EQ(TS::format_number(third), "-1/3");
  EXPECT_EQ(TS::format_number(three), "3");
}

TEST(NumberParsing, NearestDoubleRoundsCorrectly) {
  // mpq_get_d truncates; the reader must round to nearest like strtod.
  for (const char* token : {"0.1", "0.7", "1e-7", "-0.3", "2.675", "123456.789"})
    EXPECT_EQ(TS::internal::nearest_double(TS::parse_number<Exact_FT>(token)),
              TS::parse_number<double>(token))
        << token;
  EXPECT_EQ(TS::internal::nearest_double<Exact_FT>(Exact_FT(1) / Exact_FT(3)), 1.0 / 3.0);
  EXPECT_EQ(TS::internal::nearest_double<Exact_FT>(Exact_FT(-2) / Exact_FT(3)), -2.0 / 3.0);
  // Ties go to the even mantissa: 1 + 2^-53 to 1, 1 + 3 * 2^-53 to 1 + 2^-51.
  const Exact_FT u(std::ldexp(1.0, -53));
  EXPECT_EQ(TS::internal::nearest_double<Exact_FT>(Exact_FT(1) + u), 1.0);
  EXPECT_EQ(TS::internal::nearest_double<Exact_FT>(Exact_FT(1) + Exact_FT(3) * u),
            1.0 + std::ldexp(1.0, -51));
  EXPECT_EQ(TS::internal::nearest_double<Exact_FT>(Exact_FT(-1) - u), -1.0);
}

// ---------------------------------------------------------------------------------------
// Scattered data (.xyz) and Delaunay domains
// ---------------------------------------------------------------------------------------

template <class K>
class ScatteredData : public ::testing::Test {};
TYPED_TEST_SUITE(ScatteredData, Kernels, Kernel_names);

TYPED_TEST(ScatteredData, ReadsPointsCommentsAndBlankLines) {
  using K = TypeParam;
  using FT = typename K::FT;
  std::istringstream in("# x y z\n"
                        "0 0 1\n"
                        "\n"
                        "   1 0 0.1   # trailing comment\r\n"
                        "0 1 -2.5e2\n"
                        "\t0.5 0.5 3/4x\n");
  // The last line has a bad number: check the happy path without it first.
  std::istringstream good("# x y z\n0 0 1\n\n   1 0 0.1   # trailing comment\r\n0 1 -2.5e2\n"
                          "0.5\t0.5 0.75\n");
  const TS::Scattered_data<K> data = TS::read_xyz<K>(good, "good.xyz");
  ASSERT_EQ(data.points.size(), 4u);
  ASSERT_EQ(data.values.size(), 4u);
  EXPECT_EQ(data.merged_duplicates, 0u);
  EXPECT_EQ(data.points[1], typename K::Point_2(1, 0));
  EXPECT_EQ(data.values[1], TS::parse_number<FT>("0.1"));
  if (is_exact<K>) {
    EXPECT_EQ(data.values[1] * FT(10), FT(1)); // exact 1/10
  }
  EXPECT_EQ(data.values[2], FT(-250));
  EXPECT_EQ(data.points[3], typename K::Point_2(ratio<K>(1, 2), ratio<K>(1, 2)));
  EXPECT_EQ(data.values[3], ratio<K>(3, 4));
  EXPECT_TRUE(throws_with([&] { TS::read_xyz<K>(in, "bad.xyz"); }, {"bad.xyz:6:", "\"3/4x\""}));
}

TYPED_TEST(ScatteredData, EveryBlankCharacterIsBlank) {
  using K = TypeParam;
  std::istringstream in("\f\n0\v0\f1\n\v\n\r\r\n1 0 2\r\n \t\r\f\v\n0 1 3\n\f");
  const TS::Scattered_data<K> data = TS::read_xyz<K>(in, "blank.xyz");
  ASSERT_EQ(data.points.size(), 3u);
  EXPECT_EQ(data.values[0], typename K::FT(1));
}

TYPED_TEST(ScatteredData, MergesDuplicatesWithTheSameHeight) {
  using K = TypeParam;
  std::istringstream in("0 0 1\n1 0 2\n0 1 3\n1 0 2.0\n0 0 1\n0.0 1e0 3\n1 1 4\n");
  const TS::Scattered_data<K> data = TS::read_xyz<K>(in, "dup.xyz");
  EXPECT_EQ(data.merged_duplicates, 3u);
  ASSERT_EQ(data.points.size(), 4u);
  // First occurrences, in input order.
  EXPECT_EQ(data.points[0], typename K::Point_2(0, 0));
  EXPECT_EQ(data.points[1], typename K::Point_2(1, 0));
  EXPECT_EQ(data.points[2], typename K::Point_2(0, 1));
  EXPECT_EQ(data.points[3], typename K::Point_2(1, 1));
  EXPECT_EQ(data.values[3], typename K::FT(4));
}

TYPED_TEST(ScatteredData, ReadsGradientsAndKeepsThemWithTheirPoints) {
  using K = TypeParam;
  using FT = typename K::FT;
  std::istringstream in("0 0 1 0.5 -1\n1 0 2 0 0\n0 1 3 1 2\n1 0 2 0 0\n");
  const TS::Scattered_data<K> data = TS::read_xyz<K>(in, "g.xyz", true);
  ASSERT_EQ(data.gradients.size(), 3u);
  EXPECT_EQ(data.merged_duplicates, 1u);
  EXPECT_EQ(data.gradients[0][0], TS::parse_number<FT>("0.5"));
  EXPECT_EQ(data.gradients[2][1], FT(2));
  // The Delaunay numbering carries them along.
  std::vector<std::size_t> order;
  const auto [domain, values] = TS::delaunay_domain(data, &order);
  ASSERT_EQ(order.size(), 3u);
  for (std::size_t v = 0; v < 3; ++v) {
    EXPECT_EQ(domain.point(std::uint32_t(v)), data.points[order[v]]);
    EXPECT_EQ(values[v], data.values[order[v]]);
  }
  auto read = [](const std::string& text) {
    return [text] {
      std::istringstream bad(text);
      TS::read_xyz<K>(bad, "g.xyz", true);
    };
  };
  EXPECT_TRUE(throws_with(read("0 0 1 0 0\n1 0 2\n"), {"g.xyz:2:", "5 numbers (x y z zx zy)"}));
  EXPECT_TRUE(throws_with(read("0 0 1 0 0\n1 0 2 0 0\n0 1 3 1 1\n0 0 1 0 1\n"),
                          {"g.xyz:1 and g.xyz:4", "different gradients"}));
  EXPECT_TRUE(throws_with(read("0 0 1 0 nan\n"), {"g.xyz:1:"}));
  // Five numbers without gradients: a hint.
  std::istringstream five("0 0 1 0 0\n");
  EXPECT_TRUE(throws_with([&] { TS::read_xyz<K>(five, "h.xyz"); }, {"h.xyz:1:", "--gradients"}));
}

TYPED_TEST(ScatteredData, RejectsBadInput) {
  using K = TypeParam;
  auto read = [](const std::string& text) {
    return [text] {
      std::istringstream in(text);
      TS::read_xyz<K>(in, "data.xyz");
    };
  };
  EXPECT_TRUE(throws_with(read("0 0 1\n1 0 2\n# c\n0 1 3\n1 1 4\n1 0 5\n"),
                          {"data.xyz:2", "data.xyz:6", "different heights"}));
  EXPECT_TRUE(throws_with(read("0 0 1\n1 0 2\n0 0 1\n"), {"2 distinct points", "at least 3"}));
  EXPECT_TRUE(throws_with(read(""), {"0 distinct points"}));
  EXPECT_TRUE(throws_with(read("0 0 1\n1 1 2\n2 2 0\n-3 -3 1\n"),
                          {"all 4 points are collinear: no triangle"}));
  EXPECT_TRUE(throws_with(read("0 0 1\n1 0 2\n0 1\n"), {"data.xyz:3:", "expected 3 numbers"}));
  EXPECT_TRUE(throws_with(read("0 0 1 7\n"), {"data.xyz:1:", "found 4 fields"}));
  EXPECT_TRUE(throws_with(read("0 0 1\n1 nan 2\n"), {"data.xyz:2:", "\"nan\"", "not finite"}));
  EXPECT_TRUE(throws_with(read("0 0 1\n1 0 -inf\n"), {"data.xyz:2:", "\"-inf\""}));
  EXPECT_TRUE(throws_with(read("\n\n1e200 0 1\n"), {"data.xyz:3:", "\"1e200\"", "too large"}));
  EXPECT_TRUE(throws_with(read("0 0 x\n"), {"data.xyz:1:", "\"x\""}));
}

// Issue 12: vertices are numbered along a Hilbert curve (neighbours get near indices, for
// cache locality), faces by their vertices; the numbering does not depend on the input order,
// also with ties in x or y (a grid).
TYPED_TEST(ScatteredData, DelaunayDomainIsNumberedSpatiallyWhateverTheInputOrder) {
  using K = TypeParam;
  using FT = typename K::FT;
  TS::Scattered_data<K> data;
  std::mt19937 engine(3);
  std::uniform_int_distribution<int> coordinate(0, 1 << 20);
  for (int i = 0; i < 40; ++i)
    for (int j = 0; j < 40; ++j) {
      // a grid (ties in x and y) in the left half, random points in the right one
      const bool grid = i < 20;
      const double x = grid ? i : 20 + coordinate(engine) / double(1 << 20) * 20;
      const double y = grid ? j : coordinate(engine) / double(1 << 20) * 40;
      data.points.emplace_back(x, y);
      data.values.push_back(FT(i - j));
    }
  const auto [domain, values] = TS::delaunay_domain(data);
  const std::size_t n = domain.number_of_vertices();
  double gap = 0;
  for (std::uint32_t e = 0; e < domain.number_of_edges(); ++e)
    gap += std::abs(double(domain.edge(e)[1]) - double(domain.edge(e)[0]));
  gap /= double(domain.number_of_edges());
  // Numbered in the order of the triangulation's faces (as before), the mean gap was about
  // n/5; along a Hilbert curve it grows like sqrt(n) (36 here, 881 for 10^6 random points).
  EXPECT_LT(gap, 0.05 * double(n)) << "mean index gap across an edge";
  TS::Scattered_data<K> shuffled = data;
  std::vector<std::size_t> order(n);
  std::iota(order.begin(), order.end(), std::size_t(0));
  std::shuffle(order.begin(), order.end(), engine);
  for (std::size_t i = 0; i < n; ++i) {
    shuffled.points[i] = data.points[order[i]];
    shuffled.values[i] = data.values[order[i]];
  }
  const auto [again, again_values] = TS::delaunay_domain(shuffled);
  EXPECT_EQ(again.points(), domain.points());
  EXPECT_EQ(again.faces(), domain.faces());
  EXPECT_EQ(again_values, values);
}

TYPED_TEST(ScatteredData, DelaunayDomainRemovesOnlyFlatTrianglesClosingTheHull) {
  // (0, 0), (1, 0), an apex (1/2, y) above their edge and (1/2, 1): the hull triangle under
  // the apex is flat when the sines of its angles at (0, 0) and (1, 0), 2y, are at most
  // flat_hull_sine; removed, the apex joins the boundary and every point stays a vertex.
  using K = TypeParam;
  using FT = typename K::FT;
  for (const double y : {2e-10, 1e-8}) {
    TS::Scattered_data<K> data;
    using P = typename K::Point_2;
    data.points = {P(FT(0), FT(0)), P(FT(1), FT(0)), P(FT(0.5), FT(y)), P(FT(0.5), FT(1))};
    data.values = {FT(0), FT(1), FT(2), FT(3)};
    std::size_t flat = 7;
    const auto [domain, values] = TS::delaunay_domain(data, nullptr, &flat);
    const bool removed = 2 * y <= TS::flat_hull_sine;
    EXPECT_EQ(flat, removed ? 1u : 0u) << y;
    EXPECT_EQ(domain.number_of_vertices(), 4u);
    EXPECT_EQ(domain.number_of_faces(), removed ? 2u : 3u) << y;
    EXPECT_EQ(domain.number_of_boundary_edges(), 4u - (removed ? 0u : 1u)) << y;
  }
}

TYPED_TEST(ScatteredData, DelaunayDomainCarriesTheValues) {
  using K = TypeParam;
  using FT = typename K::FT;
  // A 4 x 4 grid plus two more points; z = 2x - y at every point.
  std::ostringstream text;
  for (int i = 0; i < 4; ++i)
    for (int j = 0; j < 4; ++j)
      text << i << " " << j << " " << 2 * i - j << "\n";
  text << "0.5 0.25 0.75\n1.5 2.5 0.5\n";
  std::istringstream in(text.str());
  const TS::Scattered_data<K> data = TS::read_xyz<K>(in, "grid.xyz");
  const auto [domain, values] = TS::delaunay_domain(data);
  EXPECT_EQ(domain.number_of_vertices(), 18u);
  ASSERT_EQ(values.size(), 18u);
  // The convex hull is the square [0,3]^2 with 12 boundary vertices: F = 2V - B - 2.
  EXPECT_EQ(domain.number_of_boundary_vertices(), 12u);
  EXPECT_EQ(domain.number_of_faces(), 2u * 18u - 12u - 2u);
  EXPECT_TRUE(domain.is_simply_connected());
  for (std::uint32_t v = 0; v < domain.number_of_vertices(); ++v) {
    const FT expected = FT(2) * domain.point(v).x() - domain.point(v).y();
    EXPECT_EQ(values[v], expected) << "vertex " << v;
  }
  // Hand-made data bypass read_xyz's checks; delaunay_domain has its own.
  TS::Scattered_data<K> bad;
  bad.points = {{0, 0}, {1, 0}, {0, 1}, {1, 0}};
  bad.values = {FT(0), FT(1), FT(2), FT(3)};
  EXPECT_TRUE(throws_with([&] { TS::delaunay_domain(bad); }, {"1 points repeat"}));
  bad.points = {{0, 0}, {1, 1}, {2, 2}, {3, 3}};
  EXPECT_TRUE(throws_with([&] { TS::delaunay_domain(bad); }, {"collinear"}));
  bad.values.pop_back();
  EXPECT_TRUE(throws_with([&] { TS::delaunay_domain(bad); }, {"4 points but 3 values"}));
}

// ---------------------------------------------------------------------------------------
// Meshes through CGAL IO
// ---------------------------------------------------------------------------------------

template <class K>
class MeshDomain : public ::testing::Test {};
TYPED_TEST_SUITE(MeshDomain, Kernels, Kernel_names);

TYPED_TEST(MeshDomain, ReadsOffAndObj) {
  using K = TypeParam;
  using FT = typename K::FT;
  Temporary_directory dir;
  const std::string off = dir.write("square.off", "OFF\n5 4 0\n"
                                                  "0 0 1\n2 0 2\n2 2 3\n0 2 4\n1 1 0.1\n"
                                                  "3 0 1 4\n3 1 2 4\n3 2 3 4\n3 3 0 4\n");
  const std::string obj = dir.write("square.OBJ", "# square\nv 0 0 1\nv 2 0 2\nv 2 2 3\n"
                                                  "v 0 2 4\nv 1 1 0.1\n"
                                                  "f 1 2 5\nf 2 3 5\nf 3 4 5\nf 4 1 5\n");
  const std::string ply = dir.write("square.ply", "ply\nformat ascii 1.0\nelement vertex 5\n"
                                                  "property double x\nproperty double y\n"
                                                  "property double z\nelement face 4\n"
                                                  "property list uchar int vertex_indices\n"
                                                  "end_header\n"
                                                  "0 0 1\n2 0 2\n2 2 3\n0 2 4\n1 1 0.1\n"
                                                  "3 0 1 4\n3 1 2 4\n3 2 3 4\n3 3 0 4\n");
  // STL stores corners per facet; CGAL merges equal points (numbered by first appearance).
  std::string stl = "solid square\n";
  for (const char* facet :
       {"0 0 1\nvertex 2 0 2\nvertex 1 1 0.1", "2 0 2\nvertex 2 2 3\nvertex 1 1 0.1",
        "2 2 3\nvertex 0 2 4\nvertex 1 1 0.1", "0 2 4\nvertex 0 0 1\nvertex 1 1 0.1"})
    stl += std::string("facet normal 0 0 1\nouter loop\nvertex ") + facet + "\nendloop\nendfacet\n";
  stl = dir.write("square.stl", stl + "endsolid square\n");
  for (const std::string& path : {off, obj, ply, stl}) {
    SCOPED_TRACE(path);
    const auto [domain, heights] = TS::read_mesh_domain<K>(path);
    EXPECT_EQ(domain.number_of_vertices(), 5u);
    EXPECT_EQ(domain.number_of_faces(), 4u);
    EXPECT_EQ(domain.number_of_interior_vertices(), 1u);
    ASSERT_EQ(heights.size(), 5u);
    // Coordinates and heights are the file's doubles, exactly.
    const std::vector<std::pair<typename K::Point_2, FT>> expected{
        {{0, 0}, FT(1)}, {{2, 0}, FT(2)}, {{2, 2}, FT(3)}, {{0, 2}, FT(4)}, {{1, 1}, FT(0.1)}};
    for (const auto& [point, z] : expected) {
      const auto& points = domain.points();
      const auto at = std::find(points.begin(), points.end(), point);
      ASSERT_NE(at, points.end());
      EXPECT_EQ(heights[static_cast<std::size_t>(at - points.begin())], z);
    }
    if (path != stl) {
      // Vertex v of the file is domain vertex v.
      EXPECT_EQ(domain.point(1), typename K::Point_2(2, 0));
      EXPECT_EQ(heights[0], FT(1));
      EXPECT_EQ(heights[3], FT(4));
    }
  }
}

TYPED_TEST(MeshDomain, RejectsBadMeshes) {
  using K = TypeParam;
  Temporary_directory dir;
  auto read = [](const std::string& path) { return [path] { TS::read_mesh_domain<K>(path); }; };
  const std::string quad = dir.write("quad.off", "OFF\n5 2 0\n0 0 0\n1 0 0\n1 1 0\n0 1 0\n"
                                                 "2 0 0\n3 1 4 2\n4 0 1 2 3\n");
  EXPECT_TRUE(throws_with(read(quad), {quad, "face 1 has 4 vertices", "only triangles"}));
  // Edge (0, 1) shared by three triangles.
  const std::string fin = dir.write("fin.off", "OFF\n5 3 0\n0 0 0\n2 0 0\n1 1 0\n1 -1 0\n"
                                               "1 3 0\n3 0 1 2\n3 1 0 3\n3 0 1 4\n");
  EXPECT_TRUE(throws_with(read(fin), {fin, "edge (0, 1)", "shared by 3", "non-manifold"}));
  const std::string flat = dir.write("flat.obj", "v 0 0 0\nv 1 0 0\nv 2 0 0\nv 0 1 0\n"
                                                 "f 1 2 4\nf 1 2 3\n");
  EXPECT_TRUE(throws_with(read(flat), {flat, "triangle 1", "zero area"}));
  const std::string duplicate = dir.write("duplicate.off", "OFF\n4 2 0\n0 0 0\n1 0 0\n0 1 0\n"
                                                           "0 0 5\n3 0 1 2\n3 3 1 2\n");
  EXPECT_TRUE(throws_with(read(duplicate), {"vertices 0 and 3 are the same point"}));
  const std::string empty = dir.write("empty.off", "OFF\n3 0 0\n0 0 0\n1 0 0\n0 1 0\n");
  EXPECT_TRUE(throws_with(read(empty), {empty, "no face"}));
  const std::string garbage = dir.write("garbage.off", "this is not a mesh\n");
  EXPECT_TRUE(throws_with(read(garbage), {garbage, "cannot read"}));
  const std::string missing = dir.path("missing.off");
  EXPECT_TRUE(throws_with(read(missing), {missing, "cannot open"}));
  const std::string unknown = dir.write("mesh.xyzw", "OFF\n");
  EXPECT_TRUE(throws_with(read(unknown), {unknown, "unsupported mesh file extension", ".xyzw"}));
  EXPECT_TRUE(throws_with(read(dir.path("noextension")), {"unsupported mesh file extension"}));
}

// ---------------------------------------------------------------------------------------
// Constrained domains and the demo data set
// ---------------------------------------------------------------------------------------

template <class K>
class ConstrainedDomain : public ::testing::Test {};
TYPED_TEST_SUITE(ConstrainedDomain, Kernels, Kernel_names);

TYPED_TEST(ConstrainedDomain, SquareWithAHole) {
  using K = TypeParam;
  using Point_2 = typename K::Point_2;
  const std::vector<Point_2> outer{{0, 0}, {2, 0}, {4, 0}, {4, 4}, {0, 4}};
  for (const bool clockwise_hole : {false, true}) {
    std::vector<Point_2> hole{{1, 1}, {3, 1}, {3, 3}, {1, 3}};
    if (clockwise_hole)
      std::reverse(hole.begin(), hole.end());
    const std::vector<Point_2> extra{{ratio<K>(1, 2), ratio<K>(1, 2)}, {ratio<K>(7, 2), 2}};
    const auto [domain, input] = TS::constrained_domain<K>({outer, hole}, extra);
    EXPECT_EQ(domain.number_of_vertices(), 11u);
    EXPECT_EQ(domain.number_of_boundary_loops(), 2u);
    EXPECT_EQ(domain.number_of_components(), 1u);
    EXPECT_FALSE(domain.is_simply_connected());
    // Annulus: V - E + F = 0.
    EXPECT_EQ(domain.number_of_vertices() + domain.number_of_faces(), domain.number_of_edges());
    for (const auto& t : domain.faces()) {
      const Point_2 centroid =
          CGAL::centroid(domain.point(t[0]), domain.point(t[1]), domain.point(t[2]));
      EXPECT_EQ(CGAL::bounded_side_2(hole.begin(), hole.end(), centroid, K()),
                CGAL::ON_UNBOUNDED_SIDE);
      EXPECT_EQ(CGAL::bounded_side_2(outer.begin(), outer.end(), centroid, K()),
                CGAL::ON_BOUNDED_SIDE);
    }
    // second[v] indexes the concatenated input points.
    std::vector<Point_2> all(outer);
    all.insert(all.end(), hole.begin(), hole.end());
    all.insert(all.end(), extra.begin(), extra.end());
    ASSERT_EQ(input.size(), domain.number_of_vertices());
    std::vector<int> seen(all.size(), 0);
    for (std::uint32_t v = 0; v < domain.number_of_vertices(); ++v) {
      ASSERT_LT(input[v], all.size());
      EXPECT_EQ(domain.point(v), all[input[v]]);
      ++seen[input[v]];
    }
    EXPECT_EQ(std::count(seen.begin(), seen.end(), 1), static_cast<long>(all.size()));
  }
}

TYPED_TEST(ConstrainedDomain, RejectsBadPolygonsAndPoints) {
  using K = TypeParam;
  using Point_2 = typename K::Point_2;
  using Polygons = std::vector<std::vector<Point_2>>;
  auto build = [](Polygons polygons, std::vector<Point_2> extra = {}) {
    return [polygons, extra] { TS::constrained_domain<K>(polygons, extra); };
  };
  const std::vector<Point_2> square{{0, 0}, {4, 0}, {4, 4}, {0, 4}};
  EXPECT_TRUE(throws_with(build({}), {"no boundary polygon"}));
  EXPECT_TRUE(throws_with(build({{{0, 0}, {1, 0}}}), {"polygon 0", "2 vertices"}));
  EXPECT_TRUE(throws_with(build({{{0, 0}, {2, 0}, {0, 2}, {2, 2}}}),
                          {"polygon 0 (the outer boundary) is not simple", "intersect"}));
  EXPECT_TRUE(throws_with(build({{{0, 0}, {2, 0}, {1, 0}, {1, 1}}}), {"polygon 0", "not simple"}));
  EXPECT_TRUE(throws_with(build({{{0, 0}, {2, 0}, {1, 0}}}), {"not simple: it folds back"}));
  EXPECT_TRUE(throws_with(build({{{0, 0}, {1, 0}, {2, 0}}}), {"not simple"}));
  EXPECT_TRUE(throws_with(build({{{0, 0}, {1, 0}, {1, 0}, {0, 1}}}), {"repeats vertex 1"}));
  EXPECT_TRUE(throws_with(build({square, {{1, 1}, {3, 1}, {1, 3}, {3, 3}}}),
                          {"polygon 1 (a hole) is not simple"}));
  EXPECT_TRUE(throws_with(build({square, {{5, 5}, {6, 5}, {6, 6}}}),
                          {"polygon 1 (a hole) lies outside the outer boundary"}));
  EXPECT_TRUE(throws_with(build({square, {{1, 1}, {5, 1}, {1, 2}}}),
                          {"polygon 0 (the outer boundary) and polygon 1 (a hole) intersect"}));
  EXPECT_TRUE(throws_with(build({square, {{0, 2}, {1, 1}, {1, 3}}}), {"intersect or touch"}));
  EXPECT_TRUE(throws_with(build({square,
                                 {{1, 1}, {3, 1}, {3, 3}, {1, 3}},
                                 {{ratio<K>(3, 2), ratio<K>(3, 2)}, {2, ratio<K>(3, 2)}, {2, 2}}}),
                          {"polygon 2 (a hole) lies inside polygon 1 (a hole)"}));
  const Polygons with_hole{square, {{1, 1}, {3, 1}, {3, 3}, {1, 3}}};
  EXPECT_TRUE(throws_with(build(with_hole, {{ratio<K>(1, 2), ratio<K>(1, 2)}, {2, 2}}),
                          {"extra point 1", "(2, 2)", "inside a hole"}));
  EXPECT_TRUE(throws_with(build(with_hole, {{5, 1}}),
                          {"extra point 0", "(5, 1)", "outside the outer boundary"}));
  EXPECT_TRUE(throws_with(build(with_hole, {{2, 0}}), {"extra point 0", "on the boundary"}));
  EXPECT_TRUE(throws_with(build(with_hole, {{3, 3}}), {"extra point 0", "on the boundary"}));
}

template <class K>
class DemoData : public ::testing::Test {};
TYPED_TEST_SUITE(DemoData, Kernels, Kernel_names);

TYPED_TEST(DemoData, HasAHoleACornerAndDegenerateBoundaryFrames) {
  using K = TypeParam;
  using FT = typename K::FT;
  using Point_2 = typename K::Point_2;
  const auto [domain, heights] = TS::demo_data<K>();
  EXPECT_GE(domain.number_of_vertices(), 150u);
  EXPECT_LE(domain.number_of_vertices(), 300u);
  ASSERT_EQ(heights.size(), domain.number_of_vertices());
  EXPECT_EQ(domain.number_of_components(), 1u);
  EXPECT_EQ(domain.number_of_boundary_loops(), 2u);
  EXPECT_FALSE(domain.is_simply_connected());
  // No face inside the hole [1/2, 1]^2.
  const std::vector<Point_2> hole{
      {ratio<K>(1, 2), ratio<K>(1, 2)}, {1, ratio<K>(1, 2)}, {1, 1}, {ratio<K>(1, 2), 1}};
  for (const auto& t : domain.faces())
    EXPECT_NE(CGAL::bounded_side_2(
                  hole.begin(), hole.end(),
                  CGAL::centroid(domain.point(t[0]), domain.point(t[1]), domain.point(t[2])), K()),
              CGAL::ON_BOUNDED_SIDE);
  // The re-entrant corner (3/2, 3/2) is a boundary vertex whose fan turns more than pi.
  bool corner_found = false;
  std::size_t degenerate = 0;
  for (std::uint32_t v = 0; v < domain.number_of_vertices(); ++v) {
    const auto [begin, end] = domain.neighbours(v);
    if (domain.point(v) == Point_2(ratio<K>(3, 2), ratio<K>(3, 2))) {
      corner_found = domain.is_boundary_vertex(v);
      // The interior angle exceeds pi: some neighbour lies right of the first boundary edge.
      EXPECT_TRUE(std::any_of(begin, end, [&](std::uint32_t w) {
        return CGAL::orientation(domain.point(v), domain.point(begin[0]), domain.point(w)) ==
               CGAL::RIGHT_TURN;
      }));
    }
    // A boundary vertex with one interior edge whose two apexes are collinear with it.
    if (domain.is_boundary_vertex(v) && domain.degree(v) == 3 &&
        CGAL::collinear(domain.point(begin[0]), domain.point(v), domain.point(begin[2])))
      ++degenerate;
  }
  EXPECT_TRUE(corner_found);
  EXPECT_GE(degenerate, 10u);
  // (1/2, 0) on the bottom side is such a vertex.
  for (std::uint32_t v = 0; v < domain.number_of_vertices(); ++v)
    if (domain.point(v) == Point_2(ratio<K>(1, 2), 0)) {
      EXPECT_EQ(domain.degree(v), 3u);
      const auto begin = domain.neighbours(v).first;
      EXPECT_TRUE(CGAL::collinear(domain.point(begin[0]), domain.point(v), domain.point(begin[2])));
      EXPECT_EQ(domain.point(begin[1]), Point_2(ratio<K>(1, 2), ratio<K>(1, 4)));
    }
  // Heights: f(0, 0) = 1/2 + 1 / (1 + 4 (81/16 + 9/16)) = 1/2 + 2/47.
  for (std::uint32_t v = 0; v < domain.number_of_vertices(); ++v)
    if (domain.point(v) == Point_2(0, 0)) {
      const FT expected = FT(1) / FT(2) + FT(2) / FT(47);
      EXPECT_TRUE(same_value(heights[v], expected, is_exact<K>, 1e-15));
    }
}

TEST(DemoData, BothKernelsBuildTheSameTriangulation) {
  const auto [inexact, inexact_heights] = TS::demo_data<Epick>();
  const auto [exact, exact_heights] = TS::demo_data<Exact_kernel>();
  ASSERT_EQ(inexact.number_of_vertices(), exact.number_of_vertices());
  EXPECT_EQ(inexact.faces(), exact.faces());
  for (std::uint32_t v = 0; v < exact.number_of_vertices(); ++v) {
    // Dyadic coordinates: the double points are the exact ones.
    EXPECT_EQ(Exact_FT(inexact.point(v).x()), exact.point(v).x());
    EXPECT_EQ(Exact_FT(inexact.point(v).y()), exact.point(v).y());
    EXPECT_NEAR(inexact_heights[v], CGAL::to_double(exact_heights[v]), 1e-14);
  }
}

// ---------------------------------------------------------------------------------------
// Spline files
// ---------------------------------------------------------------------------------------

namespace {

// Random control nets over every face, the patch vertices in a rotated or reversed order
// of the face so that the file's face lines must follow the patches.
template <class K, class Value>
std::vector<TS::Bezier_triangle<K, Value>> random_patches(const TS::Planar_domain<K>& domain,
                                                          int degree, unsigned seed) {
  Random_rationals random(seed);
  std::vector<TS::Bezier_triangle<K, Value>> patches;
  for (std::uint32_t f = 0; f < domain.number_of_faces(); ++f) {
    const auto& t = domain.face(f);
    std::array<std::uint32_t, 3> order = t;
    if (f % 3 == 1)
      order = {{t[1], t[2], t[0]}};
    else if (f % 3 == 2)
      order = {{t[0], t[2], t[1]}};
    std::vector<Value> net;
    for (std::size_t i = 0; i < TS::number_of_control_points(degree); ++i)
      net.push_back(random.value<K, Value>());
    patches.emplace_back(degree, domain.point(order[0]), domain.point(order[1]),
                         domain.point(order[2]), std::move(net));
  }
  return patches;
}

template <class K, class Value>
void expect_same_spline(const TS::Planar_domain<K>& domain,
                        const std::vector<TS::Bezier_triangle<K, Value>>& patches,
                        const TS::Spline_file<K, Value>& read) {
  ASSERT_EQ(read.domain().points(), domain.points());
  // The file's faces follow the patches' vertex order, so a face comes back as a rotation
  // of the original (both counter-clockwise).
  ASSERT_EQ(read.domain().number_of_faces(), domain.number_of_faces());
  for (std::uint32_t f = 0; f < domain.number_of_faces(); ++f) {
    const auto& a = read.domain().face(f);
    const auto& b = domain.face(f);
    const bool rotation = (a[0] == b[0] && a[1] == b[1] && a[2] == b[2]) ||
                          (a[0] == b[1] && a[1] == b[2] && a[2] == b[0]) ||
                          (a[0] == b[2] && a[1] == b[0] && a[2] == b[1]);
    ASSERT_TRUE(rotation) << "face " << f;
  }
  ASSERT_EQ(read.patches().size(), patches.size());
  for (std::size_t f = 0; f < patches.size(); ++f) {
    ASSERT_EQ(read.patches()[f].degree(), patches[f].degree());
    for (int i = 0; i < 3; ++i)
      EXPECT_EQ(read.patches()[f].vertex(i), patches[f].vertex(i));
    // Bit for bit: == on doubles, exact equality on rationals.
    EXPECT_TRUE(read.patches()[f].control_points() == patches[f].control_points()) << "face " << f;
  }
}

} // namespace

template <class K>
class SplineFile : public ::testing::Test {};
TYPED_TEST_SUITE(SplineFile, Kernels, Kernel_names);

TYPED_TEST(SplineFile, FunctionalRoundTrip) {
  using K = TypeParam;
  const auto [domain, heights] = TS::demo_data<K>();
  const auto patches = random_patches<K, typename K::FT>(domain, 5, 11);
  std::stringstream file;
  TS::write_spline_file(
      file,
      TS::Patch_network<K, typename decltype(patches)::value_type::Value_type>(domain, patches));
  const std::string text = file.str();
  EXPECT_EQ(text.rfind("tspline-spline 1\n", 0), 0u);
  EXPECT_NE(text.find(is_exact<K> ? "number_type exact\n" : "number_type double\n"),
            std::string::npos);
  EXPECT_NE(text.find("dimension 1\n"), std::string::npos);
  const TS::Spline_file<K> read = TS::read_spline_file<K>(file, "demo.spline");
  expect_same_spline(domain, patches, read);
}

TYPED_TEST(SplineFile, ParametricRoundTrip) {
  using K = TypeParam;
  using Vector_3 = typename K::Vector_3;
  std::istringstream xyz("0 0 0\n1 0 0\n0 1 0\n1 1 0\n0.5 0.3 0\n2 0.5 0\n");
  const auto [domain, values] = TS::delaunay_domain(TS::read_xyz<K>(xyz, "points.xyz"));
  const auto patches = random_patches<K, Vector_3>(domain, 4, 5);
  std::stringstream file;
  TS::write_spline_file(
      file,
      TS::Patch_network<K, typename decltype(patches)::value_type::Value_type>(domain, patches));
  EXPECT_NE(file.str().find("dimension 3\n"), std::string::npos);
  // The header peek finds the dimension and rewinds, so the full read still works.
  EXPECT_EQ(TS::spline_file_dimension(file), 3);
  const TS::Spline_file<K, Vector_3> read =
      TS::read_spline_file<K, Vector_3>(file, "parametric.spline");
  expect_same_spline(domain, patches, read);
  // A dimension 3 file cannot be read as heights.
  std::istringstream again(file.str());
  EXPECT_TRUE(throws_with([&] { TS::read_spline_file<K>(again, "parametric.spline"); },
                          {"parametric.spline:4:", "dimension 3", "dimension 1 values"}));
}

TYPED_TEST(SplineFile, WriterChecksPatches) {
  using K = TypeParam;
  const auto data = TS::demo_data<K>();
  const TS::Planar_domain<K>& domain = data.first; // lambdas cannot capture structured bindings
  auto patches = random_patches<K, typename K::FT>(domain, 2, 3);
  std::ostringstream out;
  using Network = TS::Patch_network<K>;
  auto fewer = patches;
  fewer.pop_back();
  EXPECT_TRUE(throws_with([&] { Network(domain, fewer); },
                          {"patch network: 255 patches for a domain of 256 faces"}));
  auto swapped = patches;
  std::swap(swapped[0], swapped[100]);
  EXPECT_TRUE(throws_with([&] { TS::write_spline_file(out, Network(domain, swapped)); },
                          {"patch 0", "is not a vertex of face 0"}));
  auto mixed = patches;
  mixed[7] = mixed[7].elevate_degree();
  EXPECT_TRUE(throws_with([&] { TS::write_spline_file(out, Network(domain, mixed)); },
                          {"patch 7 has degree 3"}));
}

// The writer formats the patches on all cores, 64 blocks of 1024 faces at a time: a network
// of more than one batch must give the text of a plain serial loop, and the first bad face's
// error wherever the bad faces sit.
// The text a serial writer gives: `text`'s header, vertex and face lines, then each patch's
// numbers as format_number() writes them.
template <class Patches>
std::string serial_spline_text(const std::string& text, const Patches& patches) {
  const std::size_t start = text.find("patches\n");
  if (start == std::string::npos)
    return "no patches line";
  std::string serial = text.substr(0, start) + "patches\n";
  for (const auto& patch : patches) {
    for (std::size_t i = 0; i < patch.control_points().size(); ++i)
      serial += (i ? " " : "") + TS::format_number(patch.control_points()[i]);
    serial += "\n";
  }
  return serial + "end\n";
}

// Patches `first` and `later` get vertices their faces do not list in that order (two
// vertices swapped): the writer names `first`, whichever thread met `later` before.
template <class K, class Patches>
void expect_first_bad_face_named(const TS::Planar_domain<K>& domain, Patches patches,
                                 std::size_t first, std::size_t later) {
  std::swap(patches[later], patches[later + 1]);
  std::swap(patches[first], patches[first + 3]);
  std::ostringstream bad;
  const std::string face = std::to_string(first);
  EXPECT_TRUE(
      throws_with([&] { TS::write_spline_file(bad, TS::Patch_network<K>(domain, patches)); },
                  {"patch " + face + " vertex", "is not a vertex of face " + face}));
}

TEST(SplineFile, ParallelWriterGivesTheSerialText) {
  using K = Epick;
  TS::Scattered_data<K> data;
  std::mt19937_64 random(5);
  std::uniform_real_distribution<double> unit(0, 1);
  for (int i = 0; i < 36000; ++i) {
    data.points.emplace_back(unit(random), unit(random));
    data.values.push_back(0);
  }
  const TS::Planar_domain<K> domain = TS::delaunay_domain(data).first;
  ASSERT_GT(domain.number_of_faces(), 65536u); // two batches
  auto patches = random_patches<K, double>(domain, 5, 3);
  std::ostringstream out;
  TS::write_spline_file(out, TS::Patch_network<K>(domain, patches));
  const std::string text = out.str();
  EXPECT_TRUE(text == serial_spline_text(text, patches));
  std::istringstream in(text);
  expect_same_spline(domain, patches, TS::read_spline_file<K>(in, "large.spline"));
  // bad faces in both batches, the later one first in the thread order
  expect_first_bad_face_named(domain, patches, 40000, 70001);
}

TEST(SplineFile, ExactWriterOnAllCoresGivesTheOneThreadText) {
  // Exact networks are formatted on all cores too, in batches of 4096 faces: the text of one
  // thread, the patches' numbers as format_number() writes them; the first bad face's error.
  using K = Exact_kernel;
  TS::Scattered_data<K> data;
  std::mt19937_64 random(8);
  std::uniform_int_distribution<int> coordinate(0, 1000000);
  for (int i = 0; i < 2600; ++i) {
    const K::FT x = K::FT(coordinate(random)) / 1000000; // reduced, as arithmetic keeps them
    data.points.emplace_back(x, K::FT(coordinate(random)) / 1000000);
    data.values.push_back(0);
  }
  const TS::Planar_domain<K> domain = TS::delaunay_domain(data).first;
  ASSERT_GT(domain.number_of_faces(), 4096u); // two batches
  auto patches = random_patches<K, K::FT>(domain, 5, 4);
  std::ostringstream all, one;
  TS::write_spline_file(all, TS::Patch_network<K>(domain, patches));
  TS::internal::thread_limit() = 1;
  TS::write_spline_file(one, TS::Patch_network<K>(domain, patches));
  TS::internal::thread_limit() = 0;
  const std::string text = all.str();
  EXPECT_TRUE(text == one.str());
  EXPECT_TRUE(text == serial_spline_text(text, patches));
  std::istringstream in(text);
  expect_same_spline(domain, patches, TS::read_spline_file<K>(in, "exact.spline"));
  expect_first_bad_face_named(domain, patches, 2000, 4500);
}

TEST(SplineFileConversion, NumberTypesConvertAsDocumented) {
  const std::string text = "# leading comment\n"
                           "tspline-spline 1\n"
                           "degree 1\n"
                           "dimension 1\n"
                           "number_type NT\n"
                           "vertices 3\n"
                           "0 0\n"
                           "1 0\n"
                           "0 0.1\n"
                           "faces 1\n"
                           "0 1 2\n"
                           "patches\n"
                           "0.1 V 2.675\n"
                           "end\n";
  auto with = [&](const std::string& type, const std::string& v) {
    std::string s = text;
    s.replace(s.find("NT"), 2, type);
    s.replace(s.find(" V "), 3, " " + v + " ");
    return s;
  };
  // exact file -> exact kernel: exact; -> double: nearest double.
  {
    std::istringstream in(with("exact", "1/3"));
    const auto read = TS::read_spline_file<Exact_kernel>(in, "e.spline");
    EXPECT_EQ(read.patches()[0].control_points()[0], Exact_FT(1) / Exact_FT(10));
    EXPECT_EQ(read.patches()[0].control_points()[1], Exact_FT(1) / Exact_FT(3));
    EXPECT_EQ(read.domain().point(2).y(), Exact_FT(1) / Exact_FT(10));
    std::istringstream in2(with("exact", "1/3"));
    const auto rounded = TS::read_spline_file<Epick>(in2, "e.spline");
    EXPECT_EQ(rounded.patches()[0].control_points()[0], 0.1);
    EXPECT_EQ(rounded.patches()[0].control_points()[1], 1.0 / 3.0);
    EXPECT_EQ(rounded.patches()[0].control_points()[2], 2.675);
    EXPECT_EQ(rounded.domain().point(2).y(), 0.1);
  }
  // double file -> exact kernel: the doubles, converted exactly.
  {
    std::istringstream in(with("double", "0.3"));
    const auto read = TS::read_spline_file<Exact_kernel>(in, "d.spline");
    EXPECT_EQ(read.patches()[0].control_points()[0], Exact_FT(0.1));
    EXPECT_EQ(read.patches()[0].control_points()[1], Exact_FT(0.3));
    EXPECT_EQ(read.domain().point(2).y(), Exact_FT(0.1));
    std::istringstream in2(with("double", "1/3"));
    EXPECT_TRUE(throws_with([&] { TS::read_spline_file<Exact_kernel>(in2, "d.spline"); },
                            {"d.spline:13:", "\"1/3\"", "not a decimal number"}));
  }
}

TYPED_TEST(SplineFile, MalformedFilesAreRejectedWithTheLine) {
  using K = TypeParam;
  // Line numbers:       1                  2          3             4
  const std::string good = "tspline-spline 1\ndegree 1\ndimension 1\nnumber_type exact\n"
                           // 5          6     7     8     9
                           "vertices 4\n0 0\n1 0\n1 1\n0 1\n"
                           // 10      11       12       13
                           "faces 2\n0 1 2\n0 2 3\npatches\n"
                           // 14        15                 16
                           "1 2 3\n1/2 0.25 -7\nend\n";
  const auto read = spline_reading<K>;
  auto replace = [&](const std::string& from, const std::string& to) {
    std::string s = good;
    const std::size_t at = s.find(from);
    EXPECT_NE(at, std::string::npos) << from;
    return s.replace(at, from.size(), to);
  };
  {
    std::istringstream in("# comment\n\n" +
                          replace("0 1\nfaces", "# the last vertex\n 0 1\n"
                                                "faces") +
                          "# trailing comment\n\n");
    const auto spline = TS::read_spline_file<K>(in, "s.spline");
    EXPECT_EQ(spline.domain().number_of_faces(), 2u);
    EXPECT_EQ(spline.patches()[1].control_points()[2], typename K::FT(-7));
  }
  EXPECT_TRUE(throws_with(read(""), {"s.spline:0:", "unexpected end of file"}));
  EXPECT_TRUE(throws_with(read(replace("tspline-spline 1", "tspline-splin 1")),
                          {"s.spline:1:", "not a tspline spline file"}));
  EXPECT_TRUE(throws_with(read(replace("tspline-spline 1", "tspline-spline 2")),
                          {"s.spline:1:", "unsupported version \"2\""}));
  EXPECT_TRUE(throws_with(read(replace("degree 1\n", "")), {"s.spline:2:", "expected \"degree"}));
  EXPECT_TRUE(throws_with(read(replace("degree 1", "degree -1")),
                          {"s.spline:2:", "invalid degree \"-1\""}));
  EXPECT_TRUE(throws_with(read(replace("degree 1", "degree 1 2")),
                          {"s.spline:2:", "one value after \"degree\""}));
  EXPECT_TRUE(
      throws_with(read(replace("degree 1", "degree 1000")), {"s.spline:2:", "out of range"}));
  EXPECT_TRUE(throws_with(read(replace("dimension 1", "dimension 3")),
                          {"s.spline:3:", "dimension 3 control values (parametric)",
                           "dimension 1 values were requested"}));
  EXPECT_TRUE(throws_with(read(replace("dimension 1", "dimension 2")),
                          {"s.spline:3:", "invalid dimension \"2\""}));
  EXPECT_TRUE(throws_with(read(replace("exact", "float")),
                          {"s.spline:4:", "invalid number_type \"float\""}));
  EXPECT_TRUE(
      throws_with(read(replace("vertices 4\n", "")), {"s.spline:5:", "expected \"vertices ...\""}));
  EXPECT_TRUE(
      throws_with(read(replace("vertices 4", "vertices 5")),
                  {"s.spline:10:", "expected 2 numbers (x y) for vertex 4 of 5", "\"faces 2\""}));
  EXPECT_TRUE(throws_with(read(replace("1 1\n", "1 1 1\n")),
                          {"s.spline:8:", "expected 2 numbers (x y) for vertex 2"}));
  EXPECT_TRUE(throws_with(read(replace("1 1\n", "1 nan\n")), {"s.spline:8:", "\"nan\""}));
  EXPECT_TRUE(
      throws_with(read(replace("1 1\n", "1 1e999\n")), {"s.spline:8:", "\"1e999\"", "too large"}));
  EXPECT_TRUE(throws_with(read(replace("faces 2", "faces x")),
                          {"s.spline:10:", "invalid face count \"x\""}));
  EXPECT_TRUE(throws_with(read(replace("0 2 3\n", "0 2 9\n")),
                          {"s.spline:12:", "uses vertex 9", "only 4 vertices"}));
  EXPECT_TRUE(throws_with(read(replace("0 2 3\n", "0 2\n")),
                          {"s.spline:12:", "expected 3 vertex indices"}));
  EXPECT_TRUE(throws_with(read(replace("0 2 3\n", "0 2 -3\n")),
                          {"s.spline:12:", "invalid vertex index \"-3\""}));
  EXPECT_TRUE(throws_with(read(replace("patches\n", "")),
                          {"s.spline:13:", "expected \"patches\"", "\"1 2 3\""}));
  EXPECT_TRUE(throws_with(
      read(replace("1 2 3\n", "1 2\n")),
      {"s.spline:14:",
       "expected 3 numbers (3 control values of dimension 1) for the patch of face 0 of 2",
       "found \"1 2\""}));
  EXPECT_TRUE(throws_with(read(replace("0.25", "0.2.5")), {"s.spline:15:", "\"0.2.5\""}));
  EXPECT_TRUE(throws_with(read(replace("1/2", "1/0")), {"s.spline:15:", "\"1/0\""}));
  EXPECT_TRUE(throws_with(read(replace("end\n", "")), {"unexpected end of file", "\"end\""}));
  EXPECT_TRUE(
      throws_with(read(replace("end\n", "finish\n")), {"s.spline:16:", "expected \"end\""}));
  EXPECT_TRUE(
      throws_with(read(good + "0 0\n"), {"s.spline:17:", "unexpected content after \"end\""}));
  // Domain validation errors propagate, prefixed with the source.
  EXPECT_TRUE(
      throws_with(read(replace("1 1\n", "2 0\n")), {"s.spline: domain: triangle 0", "zero area"}));
  EXPECT_TRUE(throws_with(
      read(replace("faces 2\n0 1 2\n0 2 3\npatches\n1 2 3\n", "faces 1\n0 1 2\npatches\n")),
      {"s.spline: domain:", "vertex 3", "not used"}));
}

// Issue 13, defect 1: a line of blanks other than space and tab ("\r\r" is enough) was taken
// for a line with a token, and the reader read a token that was not there (a segfault).
TYPED_TEST(SplineFile, BlankOnlyLinesAreBlank) {
  using K = TypeParam;
  const std::string good = "tspline-spline 1\ndegree 1\ndimension 1\nnumber_type exact\n"
                           "vertices 3\n0 0\n1 0\n0 1\nfaces 1\n0 1 2\npatches\n1 2 3\nend\n";
  for (const char* blank : {"\r", "\f", "\v", "\r\r", " \t\r\f\v"}) {
    const std::string b = blank;
    SCOPED_TRACE(::testing::PrintToString(b));
    // A blank line before every line and at the end, and blanks around every token.
    std::string text = b + "\n";
    for (char c : good)
      text += c == '\n' ? b + "\n" + b + "\n" + b : c == ' ' ? b + " " + b : std::string(1, c);
    std::istringstream in(text);
    EXPECT_EQ(TS::spline_file_dimension(in), 1);
    const auto spline = TS::read_spline_file<K>(in, "blank.spline");
    EXPECT_EQ(spline.patches().at(0).control_points().at(2), typename K::FT(3));
    for (const std::string& alone : {b, b + "\n", b + "\n" + b})
      EXPECT_TRUE(throws_with(
          [&] {
            std::istringstream only(alone);
            TS::read_spline_file<K>(only, "blank.spline");
          },
          {"blank.spline:", "unexpected end of file"}));
  }
  const std::string reproducer = std::string(TSPLINE_BAD_DATA_DIR) + "/blank_lines.spline";
  std::ifstream file(reproducer, std::ios::binary);
  ASSERT_TRUE(file) << reproducer;
  EXPECT_TRUE(throws_with([&] { TS::read_spline_file<K>(file, reproducer); },
                          {reproducer + ":1:", "unexpected end of file"}));
}

// Issue 13, defects 4 and 6: counts that cannot fit in the file fail at their line, and
// long tokens are quoted short.
TYPED_TEST(SplineFile, CountsMustFitTheFile) {
  using K = TypeParam;
  const std::string good = "tspline-spline 1\ndegree 1\ndimension 1\nnumber_type exact\n"
                           "vertices 3\n0 0\n1 0\n0 1\nfaces 1\n0 1 2\npatches\n1 2 3\nend\n";
  const auto read = spline_reading<K>;
  auto replace = [&](const std::string& from, const std::string& to) {
    std::string s = good;
    return s.replace(s.find(from), from.size(), to);
  };
  EXPECT_TRUE(throws_with(read(replace("vertices 3", "vertices 2000000000")),
                          {"s.spline:5:", "vertex count 2000000000 cannot fit", "bytes left"}));
  // 3 vertex lines and a face line fit, but not 2 faces with their patches.
  EXPECT_TRUE(
      throws_with(read(replace("faces 1", "faces 3")), {"s.spline:9:", "face count 3 cannot fit"}));
  EXPECT_TRUE(throws_with(read(replace("faces 1", "faces -1")),
                          {"s.spline:9:", "invalid face count \"-1\""}));
  const std::string digits(1000000, '7');
  try {
    read(replace("vertices 3", "vertices " + digits))();
    ADD_FAILURE() << "no exception";
  } catch (const Invalid_input& e) {
    const std::string message = e.what();
    EXPECT_LT(message.size(), 140u) << message.substr(0, 200);
    EXPECT_NE(message.find("s.spline:5: vertex count \"7777"), std::string::npos) << message;
    EXPECT_NE(message.find("...\" (1000000 characters) is out of range"), std::string::npos)
        << message;
  }
}

// Issue 13, defects 4 and 6: mesh headers are checked against the file size before CGAL's
// readers allocate, and face indices must be integers (CGAL truncated "1.5" to 1).
TYPED_TEST(MeshDomain, RejectsImpossibleCountsBeforeAllocating) {
  using K = TypeParam;
  Temporary_directory dir;
  auto read = [](const std::string& path) { return [path] { TS::read_mesh_domain<K>(path); }; };
  const std::string vertices = "0 0 0\n1 0 0\n0 1 0\n";
  const std::string off = dir.write("faces.off", "OFF\n3 2000000000 0\n" + vertices + "3 0 1 2\n");
  EXPECT_TRUE(throws_with(read(off), {off + ":2:", "announces 2000000000 faces", "-byte file"}));
  const std::string off_v = dir.write("vertices.off", "OFF 4000000000 1 0\n" + vertices);
  EXPECT_TRUE(throws_with(read(off_v), {off_v + ":1:", "announces 4000000000 vertices"}));
  // Binary OFF: big-endian int32 counts after the keyword line.
  auto binary_off = [&](const std::string& name, std::int32_t v, std::int32_t f) {
    std::string text = "OFF BINARY\n";
    for (const std::int32_t i : {v, f, 0})
      for (int shift = 24; shift >= 0; shift -= 8)
        text += static_cast<char>((static_cast<std::uint32_t>(i) >> shift) & 0xff);
    return dir.write(name, text + std::string(48, '\0'));
  };
  // (refused since altogether: CGAL read binary headers differently from every check)
  const std::string binary_faces = binary_off("binary_faces.off", 3, 2000000000);
  EXPECT_TRUE(
      throws_with(read(binary_faces), {binary_faces + ":1:", "binary OFF is not supported"}));
  const std::string binary_minus = binary_off("binary_minus.off", -3, 1);
  EXPECT_TRUE(throws_with(read(binary_minus), {binary_minus + ":1:", "binary OFF"}));
  const std::string glued_binary = std::string(TSPLINE_BAD_DATA_DIR) + "/off_binary_glued.off";
  EXPECT_TRUE(throws_with(read(glued_binary), {glued_binary + ":1:", "binary OFF"}));
  // CGAL reads "OFF#BINARY" as a binary header (the '#' is eaten with the keyword)
  const std::string glued_comment =
      std::string(TSPLINE_BAD_DATA_DIR) + "/off_comment_glued_keyword.off";
  EXPECT_TRUE(throws_with(read(glued_comment),
                          {glued_comment + ":1:", "a comment glued to the OFF keyword"}));
  const std::string negative = std::string(TSPLINE_BAD_DATA_DIR) + "/negative_count.off";
  EXPECT_TRUE(throws_with(read(negative), {negative + ":2:", "invalid face count \"-1\""}));
  const std::string huge = std::string(TSPLINE_BAD_DATA_DIR) + "/huge_count.ply";
  EXPECT_TRUE(throws_with(read(huge), {huge + ":8:", "announces 2000000000 \"face\" elements"}));
  const std::string ply_header = "ply\nformat ascii 1.0\nelement vertex 3\nproperty double x\n"
                                 "property double y\nproperty double z\nelement face F\n"
                                 "property list uchar int vertex_indices\nend_header\n";
  auto ply = [&](const std::string& name, const std::string& faces, const std::string& body) {
    std::string header = ply_header;
    return dir.write(name, header.replace(header.find(" F\n"), 3, " " + faces + "\n") + body);
  };
  const std::string minus = ply("minus.ply", "-1", vertices);
  EXPECT_TRUE(throws_with(read(minus), {minus + ":7:", "invalid element count \"-1\""}));
  // The list length of a face, ASCII and binary: CGAL resizes to it before reading.
  const std::string long_list = ply("list.ply", "1", vertices + "2000000000 0 1 2\n");
  EXPECT_TRUE(throws_with(read(long_list), {long_list + ":13:", "face 0", "2000000000 values"}));
  std::string binary = "ply\nformat binary_little_endian 1.0\nelement vertex 3\n"
                       "property float x\nproperty float y\nproperty float z\nelement face 1\n"
                       "property list int int vertex_indices\nend_header\n";
  for (const float c : {0.f, 0.f, 0.f, 1.f, 0.f, 0.f, 0.f, 1.f, 0.f})
    binary.append(reinterpret_cast<const char*>(&c), sizeof c);
  for (const std::int32_t i : {2000000000, 0, 1, 2})
    binary.append(reinterpret_cast<const char*>(&i), sizeof i);
  const std::string binary_ply = dir.write("binary.ply", binary);
  EXPECT_TRUE(throws_with(read(binary_ply), {binary_ply, "face 0", "2000000000 values"}));
  // The same file with a correct length reads.
  binary.replace(binary.size() - 16, 4, std::string("\3\0\0\0", 4));
  EXPECT_EQ(TS::read_mesh_domain<K>(dir.write("binary_ok.ply", binary)).first.number_of_faces(),
            1u);
}

// Issue 13, defect 5: overlaps between triangles that share no vertex (the local fan and
// edge checks cannot see them) and T-junctions are rejected; disjoint triangles whose
// bounding boxes meet are not.
TYPED_TEST(MeshDomain, RejectsOverlapsAndTJunctionsAnywhere) {
  using K = TypeParam;
  using Point = typename K::Point_2;
  using Index = typename TS::Planar_domain<K>::Index;
  auto read = [](const std::string& name) {
    const std::string path = std::string(TSPLINE_BAD_DATA_DIR) + "/" + name;
    return [path] { TS::read_mesh_domain<K>(path); };
  };
  EXPECT_TRUE(
      throws_with(read("crossing_triangles.off"),
                  {"crossing_triangles.off", "triangles 1 (3, 4, 5) and 0 (0, 1, 2) overlap"}));
  EXPECT_TRUE(throws_with(read("double_cover.off"), {"double_cover.off", "overlap"}));
  EXPECT_TRUE(
      throws_with(read("t_junction.off"),
                  {"t_junction.off", "vertex 3 (1, 0) lies inside edge (0, 1)", "T-junction"}));

  const std::vector<std::array<Index, 3>> two{{{0, 1, 2}}, {{3, 4, 5}}};
  auto domain = [&](std::vector<Point> points, bool check) {
    return TS::Planar_domain<K>(std::move(points), two, K(), check);
  };
  const std::vector<Point> crossing{Point(0, 0),   Point(2, 0),   Point(0, 2),
                                    Point(1, 0.5), Point(3, 0.5), Point(1, 3)};
  EXPECT_TRUE(throws_with([&] { domain(crossing, true); }, {"overlap"}));
  // Without the global test the local checks accept it: the test is what catches it.
  EXPECT_EQ(domain(crossing, false).number_of_faces(), 2u);
  // Boxes meet, triangles do not (they are 0.8 apart along the diagonal): accepted.
  const std::vector<Point> apart{Point(0, 0), Point(2, 0),   Point(0, 2),
                                 Point(2, 2), Point(1.1, 2), Point(2, 1.1)};
  EXPECT_EQ(domain(apart, true).number_of_components(), 2u);
  // Edges on one line (collinear orientation tests), apart: accepted.
  const std::vector<Point> on_one_line{Point(0, 0),    Point(2, 0), Point(1, 1),
                                       Point(1.5, -1), Point(5, 0), Point(2.5, 0)};
  EXPECT_EQ(domain(on_one_line, true).number_of_faces(), 2u);
  // A triangle inside another (no boundary edge crosses): still an overlap.
  const std::vector<Point> nested{Point(0, 0), Point(4, 0), Point(0, 4),
                                  Point(1, 1), Point(2, 1), Point(1, 2)};
  EXPECT_TRUE(throws_with([&] { domain(nested, true); }, {"overlap"}));
}

TYPED_TEST(MeshDomain, RejectsFractionalAndLongIndices) {
  using K = TypeParam;
  Temporary_directory dir;
  auto read = [](const std::string& path) { return [path] { TS::read_mesh_domain<K>(path); }; };
  const std::string fractional = std::string(TSPLINE_BAD_DATA_DIR) + "/fractional_index.off";
  EXPECT_TRUE(throws_with(read(fractional),
                          {fractional + ":6:", "face 0", "invalid vertex index \"1.5\""}));
  const std::string vertices = "0 0 0\n1 0 0\n0 1 0\n";
  for (const char* face : {"3 0 -1 2", "3 0 1e0 2", "3.0 0 1 2", "3 0 1 3", "4 0 1 2"}) {
    SCOPED_TRACE(face);
    const std::string off = dir.write("face.off", "OFF\n3 1 0\n" + vertices + face + "\n");
    EXPECT_TRUE(throws_with(read(off), {off + ":6:", "face 0"}));
  }
  for (const char* face : {"f 1 2.5 3", "f 1 0 3", "f 1 2 -4", "f 1 2 4", "f 1 2x 3"}) {
    SCOPED_TRACE(face);
    const std::string obj = dir.write("face.obj", "v " + vertices.substr(0, 6) +
                                                      "v 1 0 0\n"
                                                      "v 0 1 0\n" +
                                                      face + "\n");
    EXPECT_TRUE(throws_with(read(obj), {obj + ":4:", "face corner"}));
  }
  const std::string ply = dir.write(
      "face.ply", "ply\nformat ascii 1.0\nelement vertex 3\nproperty double x\nproperty double y\n"
                  "property double z\nelement face 1\nproperty list uchar int vertex_indices\n"
                  "end_header\n" +
                      vertices + "3 0 1.5 2\n");
  EXPECT_TRUE(throws_with(read(ply), {ply + ":13:", "face 0", "\"1.5\" is not an integer"}));
  // A megabyte index is quoted short.
  const std::string off = dir.write("long.off", "OFF\n3 1 0\n" + vertices + "3 0 1 " +
                                                    std::string(1000000, '2') + "\n");
  try {
    TS::read_mesh_domain<K>(off);
    ADD_FAILURE() << "no exception";
  } catch (const Invalid_input& e) {
    EXPECT_LT(std::string(e.what()).size(), off.size() + 160)
        << std::string(e.what()).substr(0, 300);
    EXPECT_NE(std::string(e.what()).find("(1000000 characters)"), std::string::npos);
  }
}

// Issue 13, found by fuzz/ (libFuzzer): headers that CGAL's readers accept but read
// differently from the checks, so that the checks were skipped and CGAL hit undefined
// behaviour (a face size of 1e151 converted to std::size_t, an element that does not
// exist, a null dereference in a release build).
// The last fuzz findings: CGAL 5.5 reads OFF colours and textures unchecked (heap overflow,
// out-of-range casts), and PLY headers more leniently than any imitation of it. Colours and
// textures are refused, face colours checked, PLY headers read strictly.
TYPED_TEST(MeshDomain, RefusesColouredOffAndNonStandardPlyHeaders) {
  using K = TypeParam;
  Temporary_directory dir;
  auto read = [](const std::string& path) { return [path] { TS::read_mesh_domain<K>(path); }; };
  const std::string bad = TSPLINE_BAD_DATA_DIR;
  for (const char* name :
       {"off_colour_entries.off", "off_colour_index.off", "off_colour_range.off"}) {
    const std::string path = bad + "/" + name;
    EXPECT_TRUE(throws_with(read(path), {path + ":1:", "\"COFF\"", "colours or textures"}));
  }
  const std::string vertices = "0 0 0\n1 0 0\n0 1 0\n";
  const std::string st = dir.write("st.off", "STOFF\n3 1 0\n" + vertices + "3 0 1 2\n");
  EXPECT_TRUE(throws_with(read(st), {st + ":1:", "colours or textures"}));
  for (const char* colour : {" 300", " 0.5 2.0 0", " 1 2", " 255 0 0 0 0", " -7", " 149"}) {
    SCOPED_TRACE(colour);
    const std::string off =
        dir.write("c.off", "OFF\n3 1 0\n" + vertices + "3 0 1 2" + colour + "\n");
    EXPECT_TRUE(throws_with(read(off), {off + ":6:", "face 0: invalid face colour"}));
  }
  for (const char* colour : {"", " 148", " 255 0 0", " 0.5 0.25 1 0", " 1 0 0 1"}) {
    SCOPED_TRACE(colour);
    const std::string off =
        dir.write("c.off", "OFF\n3 1 0\n" + vertices + "3 0 1 2" + colour + "\n");
    EXPECT_EQ(TS::read_mesh_domain<K>(off).first.number_of_faces(), 1u);
  }
  // CI's fuzzing: the rest of the counts' line is a face to CGAL when there is no vertex.
  const std::string counts_line = bad + "/off_face_on_counts_line.off";
  EXPECT_TRUE(throws_with(read(counts_line), {counts_line + ":3:", "values after the counts"}));
  const std::string no_vertex = dir.write("nv.off", "OFF\n0 1 0\n3 0 1 2\n");
  EXPECT_TRUE(throws_with(read(no_vertex), {no_vertex + ":2:", "no vertex"}));
  const std::string timeout = bad + "/ply_timeout.ply";
  EXPECT_TRUE(throws_with(read(timeout), {timeout + ":4:", "not printable ASCII"}));
  const std::string body = "element vertex 3\nproperty float x\nproperty float y\n"
                           "property float z\nelement face 1\n"
                           "property list uchar int vertex_indices\nend_header\n"
                           "0 0 0\n1 0 0\n0 1 0\n3 0 1 2\n";
  const std::string good = dir.write("good.ply", "ply\nformat ascii 1.0\ncomment fine\n" + body);
  EXPECT_EQ(TS::read_mesh_domain<K>(good).first.number_of_faces(), 1u);
  const std::string version = dir.write("v.ply", "ply\nformat ascii 2.0\n" + body);
  EXPECT_TRUE(throws_with(read(version), {version + ":2:", "invalid PLY header line"}));
  const std::string extra = dir.write("e.ply", "ply\nformat ascii 1.0\nelemnt x 3\n" + body);
  EXPECT_TRUE(throws_with(read(extra), {extra + ":3:", "invalid PLY header line"}));
  const std::string twice = dir.write("t.ply", "ply\nformat ascii 1.0\nelement vertex 3\n" + body);
  EXPECT_TRUE(throws_with(read(twice), {twice + ":4:", "\"vertex\" declared twice"}));
  const std::string binary = dir.write("b.ply", "ply\nformat ascii 1.0\ncomment \x01\n" + body);
  EXPECT_TRUE(throws_with(read(binary), {binary + ":3:", "not printable ASCII"}));
}

TYPED_TEST(MeshDomain, RejectsHeadersThatBypassTheChecks) {
  using K = TypeParam;
  Temporary_directory dir;
  auto read = [](const std::string& path) { return [path] { TS::read_mesh_domain<K>(path); }; };
  const std::string bad = TSPLINE_BAD_DATA_DIR;
  // CGAL's keyword ends at the first character that is not a letter or digit.
  const std::string mangled = bad + "/mangled_keyword.off";
  EXPECT_TRUE(throws_with(read(mangled), {mangled + ":1:", "invalid OFF keyword \"OFF~\""}));
  const std::string vertices = "0 0 0\n1 0 0\n0 1 0\n";
  const std::string skel = dir.write("skel.off", "SKEL\n3 1\n" + vertices + "1e151 0 1 2\n");
  EXPECT_TRUE(throws_with(read(skel), {skel + ":1:", "SKEL"}));
  // Homogeneous and n-dimensional OFF are checked like OFF (they were left to CGAL).
  const std::string homogeneous =
      dir.write("h.off", "4OFF\n3 1 0\n0 0 0 1\n1 0 0 1\n0 1 0 1\n1e151 0 1 2\n");
  EXPECT_TRUE(throws_with(read(homogeneous), {homogeneous + ":6:", "invalid vertex count"}));
  const std::string n_dimensional =
      dir.write("n.off", "nOFF\n3\n3 1 0\n" + vertices + "1e151 0 1 2\n");
  EXPECT_TRUE(throws_with(read(n_dimensional), {n_dimensional + ":7:", "invalid vertex count"}));
  const std::string many = dir.write("many.off", "4OFF 3 2000000000 0\n" + vertices);
  EXPECT_TRUE(throws_with(read(many), {many + ":1:", "announces 2000000000 faces"}));
  // Numbers glued to the counts: CGAL reads "3-10" as the dimension 3 and 10^19 vertices,
  // "0-1-2-3" as the edge count 0 and a first vertex, one line off from the checks.
  const std::string glued_dimension = bad + "/glued_dimension.off";
  EXPECT_TRUE(
      throws_with(read(glued_dimension), {glued_dimension + ":3:", "invalid dimension \"3-10\""}));
  const std::string glued_edges = bad + "/glued_edge_count.off";
  EXPECT_TRUE(
      throws_with(read(glued_edges), {glued_edges + ":2:", "invalid edge count \"0-1-2-3\""}));
  // CGAL doubles the edge count in an int.
  const std::string edges = bad + "/huge_edge_count.off";
  EXPECT_TRUE(throws_with(read(edges), {edges + ":2:", "edge count \"2147483647\" is out of"}));
  // CGAL divides by w after asserting w != 0 (a debug build threw Assertion_exception).
  const std::string w_zero = bad + "/homogeneous_zero.off";
  EXPECT_TRUE(throws_with(read(w_zero), {w_zero + ":3:", "vertex 0: w = 0"}));
  // A header cut short, with numbers glued: CGAL reads 10^19 vertices from "3-10".
  const std::string short_glued = bad + "/short_glued_header.off";
  EXPECT_TRUE(throws_with(read(short_glued), {short_glued + ":2:", "invalid header count"}));
  const std::string homogeneous_ok =
      dir.write("h_ok.off", "4OFF\n3 1 0\n0 0 0 1\n2 0 0 2\n0 3 0 3\n3 0 1 2\n");
  EXPECT_EQ(TS::read_mesh_domain<K>(homogeneous_ok).first.number_of_faces(), 1u);
  // PLY: a property before any element, and integer coordinates.
  const std::string before = bad + "/property_before_element.ply";
  EXPECT_TRUE(throws_with(read(before), {before + ":3:", "property before the first element"}));
  const std::string ply_line_1 =
      dir.write("p.ply", "ply extra\nformat ascii 1.0\nproperty float x\n");
  // (read strictly since: the first line is just "ply")
  EXPECT_TRUE(throws_with(read(ply_line_1), {ply_line_1 + ":1:", "invalid PLY header line"}));
  const std::string integer = bad + "/integer_coordinate.ply";
  EXPECT_TRUE(throws_with(read(integer), {integer + ":5:", "coordinate \"y\" must be a float"}));
  const std::string list = dir.write(
      "list.ply", "ply\nformat ascii 1.0\nelement vertex 3\nproperty list uchar float x\n");
  EXPECT_TRUE(throws_with(read(list), {list + ":4:", "coordinate \"x\""}));
  // CGAL takes the end of the file for the end of the header: 10^8 vertices from nothing.
  const std::string no_end = bad + "/no_end_header.ply";
  EXPECT_TRUE(throws_with(read(no_end), {no_end + ":3:", "no end_header"}));
  // A binary list whose length lies past the end of the file: CGAL resized to garbage.
  const std::string short_list = bad + "/short_binary_list.ply";
  EXPECT_TRUE(throws_with(read(short_list), {short_list + ": vertex 1, l: the file ends"}));
  // CGAL reads the format from line 2 whatever its first word: binary here, a list of
  // 0x20202020 ints (2 GB) from the blanks that made it an empty ASCII body for the checks.
  const std::string format = bad + "/format_line.ply";
  // (refused since at the header: line 2 must be a standard format line)
  EXPECT_TRUE(throws_with(read(format), {format + ":2:", "invalid PLY header line"}));
  // At the end of the file CGAL read a list length that was never written (4.7 GB).
  const std::string short_ascii = bad + "/short_ascii_list.ply";
  EXPECT_TRUE(throws_with(read(short_ascii), {short_ascii + ":6: vertex 0, l: the file ends"}));
  // CGAL reads "1.5-7" as the x 1.5 and then the list length -7.
  const std::string glued = bad + "/glued_number.ply";
  EXPECT_TRUE(throws_with(read(glued), {glued + ":7:", "\"1.5-7\" is not a number"}));
  // CGAL names a property by its third word: "property int y x" is the property y.
  const std::string named =
      dir.write("named.ply", "ply\nformat ascii 1.0\nelement vertex 3\nproperty int y x\n");
  // (refused since at the header: a property line has three words)
  EXPECT_TRUE(throws_with(read(named), {named + ":4:", "invalid PLY header line"}));
}

// ---------------------------------------------------------------------------------------
// NumPy .npy arrays (issue 15)
// ---------------------------------------------------------------------------------------

namespace {

// The bytes np.save writes: magic, version, header length, the dict padded to a multiple of
// 64 bytes with spaces and a newline, then the data.
std::string npy_bytes(const std::string& descr, const std::string& shape, bool fortran,
                      const std::string& data, int version = 1) {
  std::string dict = "{'descr': '" + descr + "', 'fortran_order': " + (fortran ? "True" : "False") +
                     ", 'shape': " + shape + ", }";
  const std::size_t preamble = version == 1 ? 10 : 12;
  dict.append(64 - (preamble + dict.size() + 1) % 64, ' ');
  dict += '\n';
  std::string out = "\x93NUMPY";
  out += static_cast<char>(version);
  out += '\0';
  const std::size_t n = dict.size();
  out += static_cast<char>(n & 0xff);
  out += static_cast<char>((n >> 8) & 0xff);
  if (version != 1) {
    out += static_cast<char>((n >> 16) & 0xff);
    out += static_cast<char>((n >> 24) & 0xff);
  }
  return out + dict + data;
}

template <class T>
std::string raw_bytes(std::initializer_list<T> values) {
  std::string out;
  for (T v : values) {
    unsigned char b[sizeof(T)];
    std::memcpy(b, &v, sizeof(T));
    out.append(reinterpret_cast<const char*>(b), sizeof(T)); // the test hosts are little-endian
  }
  return out;
}

TS::Npy_array read_npy_text(const std::string& bytes, const std::string& name = "a.npy") {
  std::istringstream in(bytes);
  return TS::read_npy(in, name);
}

// A stream that cannot seek (a pipe): the reader cannot know the size in advance.
class Unseekable_buffer : public std::stringbuf {
public:
  explicit Unseekable_buffer(const std::string& s) : std::stringbuf(s) {}

protected:
  pos_type seekoff(off_type, std::ios_base::seekdir, std::ios_base::openmode) override {
    return pos_type(off_type(-1));
  }
  pos_type seekpos(pos_type, std::ios_base::openmode) override { return pos_type(off_type(-1)); }
};

} // namespace

TEST(Npy, ReadsEveryVersionTypeAndOrder) {
  // The array [[1, 2, 3], [4, 5, 6]] in every supported encoding.
  const std::vector<double> expected{1, 2, 3, 4, 5, 6};
  const std::string c_f8 = raw_bytes<double>({1, 2, 3, 4, 5, 6});
  const std::string f_f8 = raw_bytes<double>({1, 4, 2, 5, 3, 6}); // column after column
  for (int version : {1, 2, 3}) {
    const TS::Npy_array a = read_npy_text(npy_bytes("<f8", "(2, 3)", false, c_f8, version));
    EXPECT_EQ(a.rows, 2u);
    EXPECT_EQ(a.columns, 3u);
    EXPECT_EQ(a.dtype, "<f8");
    EXPECT_EQ(a.values, expected) << "version " << version;
  }
  EXPECT_EQ(read_npy_text(npy_bytes("<f8", "(2, 3)", true, f_f8)).values, expected);
  EXPECT_EQ(
      read_npy_text(npy_bytes("<f4", "(2, 3)", false, raw_bytes<float>({1, 2, 3, 4, 5, 6}))).values,
      expected);
  EXPECT_EQ(
      read_npy_text(npy_bytes("<i4", "(2, 3)", true, raw_bytes<std::int32_t>({1, 4, 2, 5, 3, 6})))
          .values,
      expected);
  EXPECT_EQ(
      read_npy_text(npy_bytes("<i8", "(2, 3)", false, raw_bytes<std::int64_t>({1, 2, 3, 4, 5, 6})))
          .values,
      expected);
  // float32 values are widened exactly; negative integers keep their sign
  const TS::Npy_array f4 =
      read_npy_text(npy_bytes("<f4", "(1, 2)", false, raw_bytes<float>({0.1f, -3.5f})));
  EXPECT_EQ(f4.values[0], static_cast<double>(0.1f));
  EXPECT_EQ(
      read_npy_text(npy_bytes("<i4", "(1, 1)", false, raw_bytes<std::int32_t>({-7}))).values[0],
      -7.0);
  // what a pipe gives: read in blocks, same result
  Unseekable_buffer pipe(npy_bytes("<f8", "(2, 3)", true, f_f8));
  std::istream in(&pipe);
  EXPECT_EQ(TS::read_npy(in, "pipe.npy").values, expected);
  // the header's keys in any order, double quotes, no trailing comma
  const std::string dict = "{\"shape\": (2,3), \"fortran_order\": False, \"descr\": \"<f8\"}\n";
  std::string v1 = "\x93NUMPY\x01";
  v1 += '\0';
  v1 += static_cast<char>(dict.size());
  v1 += '\0';
  EXPECT_EQ(read_npy_text(v1 + dict + c_f8).values, expected);
}

TEST(Npy, RejectsBadFilesWithOneLine) {
  const std::string six = raw_bytes<double>({1, 2, 3, 4, 5, 6});
  auto read = [](const std::string& bytes) { return [bytes] { read_npy_text(bytes, "x.npy"); }; };
  EXPECT_TRUE(throws_with(read(""), {"x.npy: not a readable .npy file: bad magic string"}));
  EXPECT_TRUE(throws_with(read("x y z\n0 0 1\n"), {"bad magic string"}));
  EXPECT_TRUE(throws_with(read(npy_bytes("<f8", "(2, 3)", false, six, 4)), {"format version 4.0"}));
  EXPECT_TRUE(throws_with(read(npy_bytes("<f8", "(2, 3)", false, six).substr(0, 30)),
                          {"truncated header"}));
  EXPECT_TRUE(throws_with(read(npy_bytes(">f8", "(2, 3)", false, six)),
                          {"big-endian dtype '>f8'", "astype('<f8')"}));
  EXPECT_TRUE(
      throws_with(read(npy_bytes("<c16", "(2, 3)", false, six)), {"unsupported dtype '<c16'"}));
  EXPECT_TRUE(
      throws_with(read(npy_bytes("|u1", "(2, 3)", false, six)), {"unsupported dtype '|u1'"}));
  EXPECT_TRUE(throws_with(read(npy_bytes("<f8", "(6,)", false, six)),
                          {"shape (6,) is not two-dimensional"}));
  EXPECT_TRUE(throws_with(read(npy_bytes("<f8", "(1, 2, 3)", false, six)),
                          {"shape (1, 2, 3) is not two-dimensional"}));
  EXPECT_TRUE(throws_with(read(npy_bytes("<f8", "(2, 3)", false, six.substr(0, 40))),
                          {"truncated data: shape (2, 3) of '<f8' needs 48 bytes, the file holds "
                           "only 40 after the header"}));
  EXPECT_TRUE(throws_with(read(npy_bytes("<f8", "(2, 3)", false, six + "xx")),
                          {"2 bytes after the data of shape (2, 3)"}));
  // shapes whose byte count overflows, and dimensions that overflow while parsed
  EXPECT_TRUE(throws_with(read(npy_bytes("<f8", "(4611686018427387904, 4)", false, six)),
                          {"shape (4611686018427387904, 4) is too large"}));
  EXPECT_TRUE(throws_with(read(npy_bytes("<f8", "(99999999999999999999999, 3)", false, six)),
                          {"the shape's dimensions are too large"}));
  EXPECT_TRUE(throws_with(read(npy_bytes("<f8", "(2, -3)", false, six)),
                          {"tuple of non-negative integers"}));
  EXPECT_TRUE(throws_with(read(npy_bytes("<i8", "(1, 1)", false,
                                         raw_bytes<std::int64_t>({(std::int64_t(1) << 53) + 1}))),
                          {"integer 9007199254740993 at element 0 is not exactly a double"}));
  EXPECT_TRUE(throws_with(
      read(npy_bytes("<i8", "(1, 2)", false,
                     raw_bytes<std::int64_t>({0, std::numeric_limits<std::int64_t>::min()}))),
      {"integer -9223372036854775808 at element 1"}));
  // header grammar: unknown keys, structured dtypes, missing keys, oversized headers
  std::string extra = npy_bytes("<f8", "(2, 3)", false, six);
  extra.replace(extra.find("'shape'"), 7, "'shapes'");
  EXPECT_TRUE(throws_with(read(extra), {"unexpected key 'shapes'"}));
  std::string structured = "{'descr': [('x', '<f8')], 'fortran_order': False, 'shape': (2,), }\n";
  EXPECT_TRUE(throws_with(read(std::string("\x93NUMPY\x01", 7) + '\0' +
                               static_cast<char>(structured.size()) + '\0' + structured + six),
                          {"structured arrays are not read"}));
  std::string missing = "{'descr': '<f8', 'shape': (2, 3), }\n";
  EXPECT_TRUE(throws_with(read(std::string("\x93NUMPY\x01", 7) + '\0' +
                               static_cast<char>(missing.size()) + '\0' + missing + six),
                          {"it needs 'descr', 'fortran_order' and 'shape'"}));
  EXPECT_TRUE(throws_with(read(std::string("\x93NUMPY\x02", 7) + '\0' + "\xff\xff\xff\x7f"),
                          {"header of 2147483647 bytes"}));
}

TEST(Npy, HugeShapeInATinyFileAllocatesNothing) {
  // 10^12 rows announced, 96 bytes present: refused from the file size before any allocation
  // (np.load tries to allocate 21.8 TiB), and through a pipe after reading what is there.
  const std::string huge = std::string(TSPLINE_BAD_DATA_DIR) + "/npy_huge_shape.npy";
  std::ifstream file(huge, std::ios::binary);
  EXPECT_TRUE(throws_with([&] { TS::read_npy(file, huge); },
                          {huge + ": not a readable .npy file: truncated data: shape "
                                  "(1000000000000, 3) of '<f8' needs 24000000000000 bytes, "
                                  "the file holds only 96 after the header"}));
  Unseekable_buffer pipe(
      npy_bytes("<f8", "(1000000000000, 3)", false, raw_bytes<double>({1, 2, 3, 4, 5, 6})));
  std::istream in(&pipe);
  EXPECT_TRUE(throws_with([&] { TS::read_npy(in, "pipe.npy"); },
                          {"needs 24000000000000 bytes, the data end after 48"}));
}

TEST(Npy, BadFilesOfTheRepository) {
  const std::string bad = TSPLINE_BAD_DATA_DIR;
  auto read = [](const std::string& path) {
    return [path] {
      std::ifstream in(path, std::ios::binary);
      const TS::Npy_array a = TS::read_npy(in, path);
      TS::scattered_data_from_npy<Epick>(a, path, {0, 1, 2});
    };
  };
  EXPECT_TRUE(throws_with(read(bad + "/npy_bad_magic.npy"), {"bad magic string"}));
  EXPECT_TRUE(
      throws_with(read(bad + "/npy_truncated.npy"), {"needs 96 bytes, the file holds only 50"}));
  EXPECT_TRUE(throws_with(read(bad + "/npy_big_endian.npy"), {"big-endian dtype '>f8'"}));
  EXPECT_TRUE(throws_with(read(bad + "/npy_one_dimensional.npy"), {"shape (12,)"}));
  EXPECT_TRUE(throws_with(read(bad + "/npy_nan.npy"),
                          {bad + "/npy_nan.npy: row 2, column 1: NaN is not a coordinate"}));
}

TYPED_TEST(ScatteredData, FromNpyColumnsAsReadXyzChecks) {
  using K = TypeParam;
  using FT = typename K::FT;
  // columns: id, z, x, y (as a GIS export might have them)
  TS::Npy_array a;
  a.rows = 5;
  a.columns = 4;
  a.values = {7, 1, 0, 0, 8, 2, 1, 0, 9, 3, 0, 1, 10, 4, 1, 1, 11, 0.1, 0.5, 0.25};
  const TS::Scattered_data<K> data = TS::scattered_data_from_npy<K>(a, "a.npy", {2, 3, 1});
  ASSERT_EQ(data.points.size(), 5u);
  EXPECT_EQ(data.points[4], typename K::Point_2(FT(0.5), FT(0.25)));
  EXPECT_EQ(data.values[4], FT(0.1)); // the double 0.1, exactly (not 1/10)
  EXPECT_TRUE(data.gradients.empty());
  const TS::Scattered_data<K> g = TS::scattered_data_from_npy<K>(a, "a.npy", {2, 3, 1, 0, 0});
  ASSERT_EQ(g.gradients.size(), 5u);
  EXPECT_EQ(g.gradients[1][0], FT(8));
  // the checks of read_xyz(), rows numbered from 0
  TS::Npy_array dup = a;
  dup.values[4 * 4 + 2] = 1; // row 4 at (1, 0.25)...
  dup.values[4 * 4 + 3] = 0; // ... (1, 0), as row 1, with another height
  EXPECT_TRUE(throws_with(
      [&] {
        TS::scattered_data_from_npy<K>(dup, "d.npy", {2, 3, 1});
      },
      {"d.npy: row 1 and d.npy: row 4: the same point", "different heights"}));
  TS::Npy_array same = dup;
  same.values[4 * 4 + 1] = 2; // the same height: merged
  EXPECT_EQ(TS::scattered_data_from_npy<K>(same, "s.npy", {2, 3, 1}).merged_duplicates, 1u);
  TS::Npy_array inf = a;
  inf.values[3 * 4 + 2] = -std::numeric_limits<double>::infinity();
  EXPECT_TRUE(throws_with(
      [&] {
        TS::scattered_data_from_npy<K>(inf, "i.npy", {2, 3, 1});
      },
      {"i.npy: row 3, column 2: infinity is not a coordinate"}));
  TS::Npy_array large = a;
  large.values[1] = 1e200;
  EXPECT_TRUE(throws_with(
      [&] {
        TS::scattered_data_from_npy<K>(large, "l.npy", {2, 3, 1});
      },
      {"row 0, column 1: magnitude above 1e150"}));
  EXPECT_TRUE(throws_with(
      [&] {
        TS::scattered_data_from_npy<K>(a, "a.npy", {2, 3, 4});
      },
      {"no column 4 in an array of shape (5, 4)"}));
  EXPECT_TRUE(throws_with(
      [&] {
        TS::scattered_data_from_npy<K>(a, "a.npy", {2, 3});
      },
      {"3 columns (x, y, z) or 5"}));
  TS::Npy_array line = a;
  line.rows = 2;
  line.values.resize(8);
  EXPECT_TRUE(throws_with(
      [&] {
        TS::scattered_data_from_npy<K>(line, "t.npy", {2, 3, 1});
      },
      {"t.npy: 2 distinct points"}));
  // query points: the first two columns
  const auto q = TS::query_points_from_npy<K>(a, "q.npy");
  ASSERT_EQ(q.size(), 5u);
  EXPECT_EQ(q[1], typename K::Point_2(8, 2));
  TS::Npy_array one;
  one.rows = 1;
  one.columns = 1;
  one.values = {0};
  EXPECT_TRUE(throws_with([&] { TS::query_points_from_npy<K>(one, "q.npy"); },
                          {"query points need 2 columns"}));
}
