#include "meshdiff/error.h"

#include <gtest/gtest.h>

#include <stdexcept>
#include <string>

using namespace meshdiff;

namespace {

template <class E>
void expect_catchable_as_error(const char* name)
{
    try {
        throw E(std::string("message of ") + name);
    } catch (const Error& e) {
        EXPECT_EQ(std::string(e.what()), std::string("message of ") + name);
        EXPECT_NE(dynamic_cast<const E*>(&e), nullptr) << name;
        return;
    }
    ADD_FAILURE() << name << " is not caught as meshdiff::Error";
}

}  // namespace

TEST(Error, EveryClassIsAnErrorAndARuntimeErrorWithItsMessage)
{
    expect_catchable_as_error<IoError>("IoError");
    expect_catchable_as_error<InvalidMeshError>("InvalidMeshError");
    expect_catchable_as_error<InvalidArgumentError>("InvalidArgumentError");
    expect_catchable_as_error<SolverError>("SolverError");
    static_assert(std::is_base_of_v<std::runtime_error, Error>);
}

TEST(Error, TheClassesAreDistinct)
{
    // The CLI maps each class to its own exit code: none may be caught as another.
    EXPECT_THROW(
        {
            try {
                throw IoError("x");
            } catch (const InvalidMeshError&) {
                ADD_FAILURE() << "IoError caught as InvalidMeshError";
            }
        },
        IoError);
    EXPECT_FALSE((std::is_base_of_v<InvalidArgumentError, SolverError>));
    EXPECT_FALSE((std::is_base_of_v<IoError, InvalidMeshError>));
    EXPECT_FALSE((std::is_base_of_v<InvalidMeshError, IoError>));
}
