//! \file enum_names.h
//! \brief One spelling per option value. Every option enum of meshdiff has one
//! table of names, EnumNames<E>, specialised next to the enum; to_string(),
//! parse_enum() and enum_names() are derived from it, and the same spellings
//! appear in the command line, the JSON and the text reports.
#pragma once

#include "meshdiff/error.h"

#include <array>
#include <cstddef>
#include <string>
#include <vector>

namespace meshdiff {

//! One entry of a name table.
template <class E>
struct EnumName
{
    E value;
    const char* name;
};

//! The name table of an option enum E. Each specialisation has
//! `static constexpr const char* what` (what the value is, for messages) and
//! `static constexpr std::array<EnumName<E>, N> names` (every value once).
template <class E>
struct EnumNames
{};

//! True if \p value is in the table of E (an enum can hold other values).
template <class E, class = decltype(EnumNames<E>::names)>
bool is_known(E value)
{
    for (const auto& entry : EnumNames<E>::names)
        if (entry.value == value) return true;
    return false;
}

//! The spelling of \p value; "?" for a value outside the table.
template <class E, class = decltype(EnumNames<E>::names)>
std::string to_string(E value)
{
    for (const auto& entry : EnumNames<E>::names)
        if (entry.value == value) return entry.name;
    return "?";
}

//! Every spelling of E, in table order (for the CLI's choice lists).
template <class E, class = decltype(EnumNames<E>::names)>
std::vector<std::string> enum_names()
{
    std::vector<std::string> out;
    for (const auto& entry : EnumNames<E>::names) out.emplace_back(entry.name);
    return out;
}

//! The value spelt \p name.
//! \throw InvalidArgumentError naming what E is and listing the spellings.
template <class E, class = decltype(EnumNames<E>::names)>
E parse_enum(const std::string& name)
{
    const auto& names = EnumNames<E>::names;
    for (const auto& entry : names)
        if (name == entry.name) return entry.value;
    std::string expected;
    for (std::size_t i = 0; i < names.size(); ++i) {
        if (i > 0) expected += i + 1 == names.size() ? " or " : ", ";
        expected += names[i].name;
    }
    throw InvalidArgumentError(std::string(EnumNames<E>::what) + " '" + name + "' is unknown (expected " + expected +
                               ")");
}

}  // namespace meshdiff
