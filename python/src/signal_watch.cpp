#include "signal_watch.hpp"

namespace wtc::python {

void SignalWatch::observe(const sim::Run& /*run*/) {
  const auto now = std::chrono::steady_clock::now();
  if (now < next_ || raised_) return;
  next_ = now + std::chrono::duration_cast<std::chrono::steady_clock::duration>(
                    std::chrono::duration<double>(kSignalCheckSeconds));
  py::gil_scoped_acquire gil;
  check();
}

bool SignalWatch::check() {
  if (raised_) return true;
  if (PyErr_CheckSignals() == 0) return false;
  raised_.emplace();  // takes the raised exception (error_already_set fetches it)
  stop_ = true;
  return true;
}

void SignalWatch::raiseIfSignalled() {
  if (raised_) {
    py::error_already_set e = std::move(*raised_);
    raised_.reset();
    throw e;
  }
}

}  // namespace wtc::python
