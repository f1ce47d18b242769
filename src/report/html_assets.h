//! \file html_assets.h
//! \brief The scripts and style the HTML report inlines, compiled into the
//! library (cmake/embed_assets.cmake writes their definitions at build time
//! from Debian's libjs-three and from src/report/html/).
#pragma once

#include <string_view>

namespace meshdiff::assets {

std::string_view three_js();           //!< three.js (three.min.js)
std::string_view orbit_controls_js();  //!< three.js's OrbitControls (examples/js: sets THREE.OrbitControls)
std::string_view report_js();          //!< src/report/html/report.js: the page's own script
std::string_view report_css();         //!< src/report/html/report.css: its style
std::string_view summary_js();         //!< src/report/html/summary.js: the batch summary page's script
std::string_view summary_css();        //!< src/report/html/summary.css: its style beside report.css

}  // namespace meshdiff::assets
