#include "cli.h"

#include <string>
#include <vector>

int main(int argc, char** argv)
{
    std::vector<std::string> args(argv, argv + argc);
    return meshdiff::cli::run(args);
}
