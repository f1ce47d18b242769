//! \file interrupt.h
//! \brief Ctrl-C and the progress hook of the module's calls (docs/python.md):
//! the library's Progress (core/progress.h) seen from Python.
#pragma once

#include "meshdiff/core/progress.h"

#include <pybind11/pybind11.h>

#include <atomic>
#include <chrono>
#include <cstddef>
#include <memory>
#include <string_view>
#include <thread>

namespace meshdiff::python {

namespace py = pybind11;

//! The Progress of one call of the module, made on the Python thread that
//! called it. That thread, about every 20 ms while the library reports or asks
//! whether to stop, takes the GIL, runs the Python signal handlers
//! (PyErr_CheckSignals: Ctrl-C raises KeyboardInterrupt there) and calls the
//! progress hook if one is set, hook(stage, done, total). An exception from
//! either cancels the call: the library stops within a few hundredths of the
//! stage and the exception is raised in its place (rethrow_pending()). Other
//! threads only read the cancellation flag.
class CallProgress : public Progress
{
public:
    //! With the GIL held; \p hook is None or a callable.
    explicit CallProgress(py::object hook);
    ~CallProgress() override;
    CallProgress(const CallProgress&) = delete;
    CallProgress& operator=(const CallProgress&) = delete;

    void stage(std::string_view name, std::size_t total) override;
    void advance(std::size_t done) override;
    bool cancelled() const override;

    //! With the GIL held, after the call: hands the exception that cancelled
    //! it (if any) to translate_cancelled(); when the call finished anyway, a
    //! KeyboardInterrupt is raised again at Python's next check.
    void settle(bool unwinding);

private:
    void poll(bool force) const;
    void report() const;

    std::thread::id owner_;
    py::object hook_;
    std::string_view stage_;
    std::size_t total_ = 0;
    std::atomic<std::size_t> done_{0};
    mutable std::atomic<bool> stop_{false};
    mutable std::chrono::steady_clock::time_point last_poll_;
    mutable PyObject* error_[3] = {nullptr, nullptr, nullptr};
};

//! The hook of the calls the calling thread makes next (None: none), set by
//! meshdiff._meshdiff._set_progress() around a call (the package's progress=).
py::object current_hook();

//! Registers _set_progress() in \p m.
void def_progress(py::module_& m);

//! The exception that cancelled the calling thread's last call restored as the
//! Python error (KeyboardInterrupt when there is none): for translate_exceptions().
void translate_cancelled();

}  // namespace meshdiff::python
