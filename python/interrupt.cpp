#include "interrupt.h"

#include <algorithm>
#include <utility>

namespace meshdiff::python {

namespace {

constexpr auto kPollInterval = std::chrono::milliseconds(20);

// The hook of the next calls on this thread: a strong reference owned here
// (set and cleared by _set_progress() with the GIL held).
thread_local PyObject* g_hook = nullptr;
// The exception that cancelled this thread's last call, until translated.
thread_local PyObject* g_pending[3] = {nullptr, nullptr, nullptr};

void set_progress(const py::object& hook)
{
    PyObject* previous = g_hook;
    g_hook = hook.is_none() ? nullptr : hook.inc_ref().ptr();
    Py_XDECREF(previous);
}

}  // namespace

py::object current_hook()
{
    return g_hook ? py::reinterpret_borrow<py::object>(g_hook) : py::none();
}

void def_progress(py::module_& m)
{
    m.def("_set_progress", &set_progress, "the progress hook of this thread's next calls (None: none); internal",
          py::arg("hook"));
}

void translate_cancelled()
{
    if (g_pending[0]) {
        PyErr_Restore(g_pending[0], g_pending[1], g_pending[2]);
        g_pending[0] = g_pending[1] = g_pending[2] = nullptr;
    } else {
        PyErr_SetNone(PyExc_KeyboardInterrupt);
    }
}

CallProgress::CallProgress(py::object hook)
    : owner_(std::this_thread::get_id()), hook_(std::move(hook)), last_poll_(std::chrono::steady_clock::now())
{}

CallProgress::~CallProgress()
{
    // settle() took the error; this only guards against a path that did not call it.
    if (error_[0] && Py_IsInitialized()) {
        const py::gil_scoped_acquire gil;
        Py_XDECREF(error_[0]);
        Py_XDECREF(error_[1]);
        Py_XDECREF(error_[2]);
    }
}

void CallProgress::stage(std::string_view name, std::size_t total)
{
    if (std::this_thread::get_id() != owner_) return;
    if (!stage_.empty() && total_ != 0) {  // the previous stage's end (its last advance() may not have been shown)
        done_ = total_;
        poll(true);
    }
    stage_ = name;
    total_ = total;
    done_ = 0;
    poll(true);
}

void CallProgress::advance(std::size_t done)
{
    std::size_t seen = done_.load(std::memory_order_relaxed);
    while (done > seen && !done_.compare_exchange_weak(seen, done, std::memory_order_relaxed)) {}
    if (std::this_thread::get_id() == owner_) poll(false);
}

bool CallProgress::cancelled() const
{
    if (std::this_thread::get_id() == owner_) poll(false);
    return stop_.load(std::memory_order_relaxed);
}

void CallProgress::poll(bool force) const
{
    if (stop_.load(std::memory_order_relaxed)) return;
    const auto now = std::chrono::steady_clock::now();
    if (!force && now - last_poll_ < kPollInterval) return;
    last_poll_ = now;
    const py::gil_scoped_acquire gil;
    if (PyErr_CheckSignals() == 0) report();
    if (PyErr_Occurred()) {
        PyErr_Fetch(&error_[0], &error_[1], &error_[2]);
        stop_ = true;
    }
}

// With the GIL held: hook(stage, done, total); a Python error stays set.
void CallProgress::report() const
{
    if (hook_.is_none() || stage_.empty()) return;
    const std::size_t done = std::min(done_.load(std::memory_order_relaxed), total_ ? total_ : done_.load());
    try {
        hook_(py::str(stage_.data(), stage_.size()), done, total_);
    } catch (py::error_already_set& e) {
        e.restore();  // poll() takes it
    }
}

void CallProgress::settle(bool unwinding)
{
    if (!error_[0]) {
        if (!unwinding) {  // the last stage's end, for a bar
            done_ = total_ ? total_ : done_.load();
            report();
            if (PyErr_Occurred()) PyErr_Clear();
        }
        return;
    }
    const bool interrupt = PyErr_GivenExceptionMatches(error_[0], PyExc_KeyboardInterrupt);
    if (unwinding) {
        Py_XDECREF(g_pending[0]);
        Py_XDECREF(g_pending[1]);
        Py_XDECREF(g_pending[2]);
        std::copy(error_, error_ + 3, g_pending);
    } else {
        Py_XDECREF(error_[0]);
        Py_XDECREF(error_[1]);
        Py_XDECREF(error_[2]);
        if (interrupt) PyErr_SetInterrupt();  // the call finished first: raise it at the next check
    }
    error_[0] = error_[1] = error_[2] = nullptr;
}

}  // namespace meshdiff::python
