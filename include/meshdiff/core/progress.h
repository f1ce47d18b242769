//! \file progress.h
//! \brief Progress reports and cancellation of long computations. A caller
//! hands a Progress to meshdiff (CompareOptions::progress,
//! ProfileOptions::progress, or a ProgressScope around any call); meshdiff then
//! names each stage it enters (reading, curvature, rings, metric levels, index,
//! sampling, distances, certification), reports the work done in it about every
//! 1/100 of the stage, and asks cancelled() at the same points. Once
//! cancelled() is true, the running stage skips its remaining work and the
//! call throws Cancelled (error.h) within a few hundredths of the stage.
//! Serial steps are checked in between (so topology_report() and mesh_facts()
//! can throw Cancelled too, under a cancelled Progress).
//! Without a Progress (the default) none of this costs anything.
#pragma once

#include <cstddef>
#include <string_view>

namespace meshdiff {

//! What meshdiff reports to, and asks whether to stop. Every member has a
//! default that does nothing (and is never cancelled): override what you need.
class Progress
{
public:
    Progress() = default;
    Progress(const Progress&) = delete;
    Progress& operator=(const Progress&) = delete;
    virtual ~Progress() = default;

    //! A stage begins: \p name (a literal that outlives the call), \p total
    //! units of work (vertices, batches, samples), or 0 if the total is not
    //! known in advance (certification: bound evaluations). Called on the thread
    //! that called meshdiff, outside parallel regions.
    virtual void stage(std::string_view name, std::size_t total)
    {
        static_cast<void>(name);
        static_cast<void>(total);
    }
    //! \p done units of the current stage are finished. Called from any of
    //! meshdiff's worker threads, possibly concurrently and not always in
    //! increasing order (keep the largest); must be thread-safe and cheap. A
    //! stage with a known total ends with done == total; a stage with total 0
    //! ends with the final count.
    virtual void advance(std::size_t done) { static_cast<void>(done); }
    //! True once the computation should stop. Called from any thread, at the
    //! same points as advance(); must be thread-safe and cheap.
    virtual bool cancelled() const { return false; }
};

//! Makes \p progress the Progress of every meshdiff call made on this thread
//! while the scope lives (the calls that take a Progress in their options use
//! that one when it is set). Scopes nest: the destructor restores the previous
//! one. A null \p progress switches reporting off inside the scope.
class ProgressScope
{
public:
    explicit ProgressScope(Progress* progress);
    ~ProgressScope();
    ProgressScope(const ProgressScope&) = delete;
    ProgressScope& operator=(const ProgressScope&) = delete;

private:
    Progress* previous_;
};

//! The Progress of the innermost ProgressScope on this thread, or nullptr.
Progress* current_progress();

//! \throw Cancelled if \p progress is set and cancelled.
void check_cancelled(const Progress* progress);

}  // namespace meshdiff
