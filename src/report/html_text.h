//! \file html_text.h
//! \brief Text escaping shared by the HTML pages (html.cpp, html_summary.cpp).
#pragma once

#include <string>

namespace meshdiff::html_text {

//! \p text with "</" written "<\/" (the same JSON, and no "</script>" can end the element early).
inline std::string script_safe(const std::string& text)
{
    std::string out;
    out.reserve(text.size() + 16);
    for (std::size_t i = 0; i < text.size(); ++i) {
        out += text[i];
        if (text[i] == '<' && i + 1 < text.size() && text[i + 1] == '/') out += '\\';
    }
    return out;
}

//! \p s with &, <, > and " escaped, for element text and quoted attribute values.
inline std::string escape_html(const std::string& s)
{
    std::string out;
    for (char ch : s) {
        switch (ch) {
            case '&':
                out += "&amp;";
                break;
            case '<':
                out += "&lt;";
                break;
            case '>':
                out += "&gt;";
                break;
            case '"':
                out += "&quot;";
                break;
            default:
                out += ch;
        }
    }
    return out;
}

}  // namespace meshdiff::html_text
