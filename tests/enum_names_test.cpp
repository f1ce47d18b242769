#include "meshdiff/enum_names.h"

#include <gtest/gtest.h>

#include "meshdiff/distance/distance_kind.h"
#include "meshdiff/error.h"
#include "meshdiff/geometry/sampling.h"
#include "meshdiff/io/facts.h"
#include "meshdiff/roughness/curvature.h"
#include "meshdiff/studies/noise.h"
#include "meshdiff/studies/smoothing.h"

#include <cctype>
#include <set>
#include <string>
#include <type_traits>
#include <vector>

using namespace meshdiff;

namespace {

// The spellings of every option enum with an EnumNames table (grep `struct
// EnumNames<` in include/), in declaration order of the enum: they are what the
// command line, the JSON and the text reports use, so they are spelt out here.
template <class E>
struct Spellings;
#define MESHDIFF_SPELLINGS(E, ...)                                      \
    template <>                                                         \
    struct Spellings<E>                                                 \
    {                                                                   \
        static std::vector<std::string> get() { return {__VA_ARGS__}; } \
    }
MESHDIFF_SPELLINGS(CurvatureMethod, "goldfeather", "quadric", "meyer", "jet");
MESHDIFF_SPELLINGS(RowWeighting, "none", "inverse-square");
MESHDIFF_SPELLINGS(FaceSampling, "similar", "montecarlo");
MESHDIFF_SPELLINGS(NoiseUnit, "edge", "diagonal", "absolute");
MESHDIFF_SPELLINGS(NoiseDirection, "normal", "random");
MESHDIFF_SPELLINGS(NoiseDistribution, "uniform", "gaussian");
MESHDIFF_SPELLINGS(SmoothingMethod, "laplacian", "taubin", "bilaplacian", "mcf", "modified-mcf");
MESHDIFF_SPELLINGS(SmoothingUpdate, "post", "pre");
MESHDIFF_SPELLINGS(StepControl, "fixed", "adaptive");
MESHDIFF_SPELLINGS(WarningKind, "unreferenced-vertices", "repeated-corner-faces", "isolated-vertices", "non-manifold",
                   "orientation-conflicts", "degenerate-faces", "duplicate-faces", "open-surface", "components",
                   "undefined-curvature", "outliers-dominate", "no-defined-d", "capped-neighbourhoods",
                   "sparse-neighbourhoods", "steep-fits");
MESHDIFF_SPELLINGS(DistanceKind, "surface-to-surface", "point-to-surface", "surface-to-point", "point-to-point");
#undef MESHDIFF_SPELLINGS

template <class E>
E from_int(int i)
{
    return static_cast<E>(static_cast<std::underlying_type_t<E>>(i));
}

template <class E>
std::string parse_error(const std::string& name)
{
    try {
        parse_enum<E>(name);
    } catch (const InvalidArgumentError& e) {
        return e.what();
    }
    return "no InvalidArgumentError";
}

template <class E>
class EnumNamesTest : public ::testing::Test
{};
using OptionEnums =
    ::testing::Types<CurvatureMethod, RowWeighting, FaceSampling, NoiseUnit, NoiseDirection, NoiseDistribution,
                     SmoothingMethod, SmoothingUpdate, StepControl, WarningKind, DistanceKind>;
TYPED_TEST_SUITE(EnumNamesTest, OptionEnums);

}  // namespace

TYPED_TEST(EnumNamesTest, EveryValueOfTheEnumIsSpeltAsDocumentedInDeclarationOrder)
{
    using E = TypeParam;
    const auto want = Spellings<E>::get();
    ASSERT_EQ(EnumNames<E>::names.size(), want.size());
    for (std::size_t i = 0; i < want.size(); ++i) {
        const E value = from_int<E>(int(i));
        EXPECT_TRUE(is_known(value)) << i;
        EXPECT_EQ(to_string(value), want[i]);
        EXPECT_EQ(parse_enum<E>(want[i]), value);
    }
}

TYPED_TEST(EnumNamesTest, ToStringAndParseEnumRoundTripOverTheTable)
{
    using E = TypeParam;
    for (const auto& entry : EnumNames<E>::names) {
        EXPECT_EQ(parse_enum<E>(to_string(entry.value)), entry.value);
        EXPECT_EQ(to_string(parse_enum<E>(entry.name)), entry.name);
    }
}

TYPED_TEST(EnumNamesTest, EnumNamesListsTheTableInOrder)
{
    using E = TypeParam;
    const auto names = enum_names<E>();
    ASSERT_EQ(names.size(), EnumNames<E>::names.size());
    for (std::size_t i = 0; i < names.size(); ++i) EXPECT_EQ(names[i], EnumNames<E>::names[i].name);
    EXPECT_EQ(names, Spellings<E>::get());
}

TYPED_TEST(EnumNamesTest, SpellingsAndValuesAreUnique)
{
    using E = TypeParam;
    std::set<std::string> spellings;
    std::set<std::underlying_type_t<E>> values;
    for (const auto& entry : EnumNames<E>::names) {
        EXPECT_TRUE(spellings.insert(entry.name).second) << entry.name;
        EXPECT_TRUE(values.insert(static_cast<std::underlying_type_t<E>>(entry.value)).second) << entry.name;
        EXPECT_FALSE(std::string(entry.name).empty());
    }
}

TYPED_TEST(EnumNamesTest, AnUnknownNameThrowsNamingTheKindAndEverySpelling)
{
    using E = TypeParam;
    const std::vector<std::string> unknown = {"no-such-value", "", std::string(EnumNames<E>::names[0].name) + " "};
    for (const std::string& bad : unknown) {
        const std::string message = parse_error<E>(bad);
        EXPECT_NE(message.find(EnumNames<E>::what), std::string::npos) << message;
        EXPECT_NE(message.find("'" + bad + "'"), std::string::npos) << message;
        for (const auto& name : Spellings<E>::get()) EXPECT_NE(message.find(name), std::string::npos) << message;
    }
    // Case matters: the upper-case spelling is not a name.
    std::string upper = EnumNames<E>::names[0].name;
    for (char& c : upper) c = char(std::toupper(static_cast<unsigned char>(c)));
    EXPECT_THROW(parse_enum<E>(upper), InvalidArgumentError);
}

TYPED_TEST(EnumNamesTest, AValueOutsideTheTableIsUnknownAndSpeltQuestionMark)
{
    using E = TypeParam;
    for (const int i : {int(EnumNames<E>::names.size()), int(EnumNames<E>::names.size()) + 7, 99}) {
        const E value = from_int<E>(i);
        EXPECT_FALSE(is_known(value)) << i;
        EXPECT_EQ(to_string(value), "?") << i;
    }
}

TEST(EnumNames, FaceSamplingIsSpeltSimilarAndMontecarlo)
{
    EXPECT_EQ(to_string(FaceSampling::SimilarTriangles), "similar");
    EXPECT_EQ(to_string(FaceSampling::MonteCarlo), "montecarlo");
    EXPECT_EQ(parse_enum<FaceSampling>("montecarlo"), FaceSampling::MonteCarlo);
}

TEST(EnumNames, TheMessageListsTheSpellingsWithCommasAndOr)
{
    EXPECT_EQ(parse_error<FaceSampling>("lattice"),
              "face sampling 'lattice' is unknown (expected similar or montecarlo)");
    EXPECT_EQ(parse_error<CurvatureMethod>("cubic"),
              "curvature method 'cubic' is unknown (expected goldfeather, quadric, meyer or jet)");
}
