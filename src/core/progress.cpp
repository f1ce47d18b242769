#include "meshdiff/core/progress.h"

#include "meshdiff/error.h"

namespace meshdiff {

namespace {
thread_local Progress* g_current = nullptr;
}  // namespace

ProgressScope::ProgressScope(Progress* progress) : previous_(g_current)
{
    g_current = progress;
}

ProgressScope::~ProgressScope()
{
    g_current = previous_;
}

Progress* current_progress()
{
    return g_current;
}

void check_cancelled(const Progress* progress)
{
    if (progress && progress->cancelled()) throw Cancelled();
}

}  // namespace meshdiff
