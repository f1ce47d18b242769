// Uses the presentation target meshdiff::report of the installed package: the
// comparison of two meshes as the "meshdiff.compare/1" JSON document.
// Usage: compare_json ORIGINAL PROCESSED
#include "meshdiff/compare.h"
#include "meshdiff/error.h"
#include "meshdiff/io/io.h"
#include "meshdiff/report/json.h"

#include <iostream>

int main(int argc, char** argv)
{
    if (argc != 3) {
        std::cerr << "usage: " << argv[0] << " ORIGINAL PROCESSED\n";
        return 2;
    }
    try {
        meshdiff::CompareOptions options;
        options.profile.levels = {1, 2, 5};
        options.sampling.samples = 20000;
        const meshdiff::Comparison c =
            meshdiff::compare_meshes(meshdiff::read_mesh(argv[1]), meshdiff::read_mesh(argv[2]), options);
        const nlohmann::json j = meshdiff::comparison_json(c);
        std::cout << j["schema"].get<std::string>() << " hausdorff " << j["surface_distance"]["hausdorff"]["upper"]
                  << "\n";
    } catch (const meshdiff::Error& e) {
        std::cerr << "error: " << e.what() << "\n";
        return 1;
    }
    return 0;
}
