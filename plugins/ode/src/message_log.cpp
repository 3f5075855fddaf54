#include "wtc/ode/message_log.hpp"

#include <ode/ode.h>

#include <algorithm>
#include <atomic>
#include <cstdio>
#include <mutex>

namespace wtc::ode {
namespace {

// The process-wide state behind ODE's one handler (see the header): how
// many logs exist, and the handler WTC's replaced. `replaced` is atomic:
// the handler reads it on any thread while a log may be made or destroyed
// on another.
std::mutex& handlerLock() {
  static std::mutex lock;
  return lock;
}
int g_logs = 0;  // guarded by handlerLock()
std::atomic<dMessageFunction*> g_replaced{nullptr};
thread_local MessageLog* t_capturing = nullptr;

// ODE's own printing of a message when no handler is set (its error.cpp,
// printMessage), so that an uncaptured message reads as it always did.
void printAsOde(int number, const char* format, std::va_list args) {
  std::fflush(stderr);
  std::fflush(stdout);
  if (number != 0) {
    std::fprintf(stderr, "\nODE Message %d: ", number);
  } else {
    std::fprintf(stderr, "\nODE Message: ");
  }
  std::vfprintf(stderr, format, args);
  std::fprintf(stderr, "\n");
  std::fflush(stderr);
}

extern "C" void onOdeMessage(int number, const char* format, std::va_list args) {
  if (MessageLog* log = t_capturing; log != nullptr) {
    log->add(number, format, args);
  } else if (dMessageFunction* replaced = g_replaced.load(); replaced != nullptr) {
    replaced(number, format, args);
  } else {
    printAsOde(number, format, args);
  }
}

// The length of the printf conversion that starts at format[at] == '%'
// (flags, width, precision, length modifiers, then the conversion letter).
std::size_t conversionLength(std::string_view format, std::size_t at) {
  std::size_t end = at + 1;
  while (end < format.size() && std::string_view("-+ #0123456789.*hlLqjzt").find(format[end]) != std::string_view::npos)
    ++end;
  return std::min(end + 1, format.size()) - at;
}

}  // namespace

MessageLog::MessageLog(Keep keep) : keep_(keep) {
  const std::lock_guard<std::mutex> lock(handlerLock());
  if (g_logs++ == 0) {
    g_replaced.store(dGetMessageHandler());
    dSetMessageHandler(&onOdeMessage);
  }
}

MessageLog::~MessageLog() {
  const std::lock_guard<std::mutex> lock(handlerLock());
  if (--g_logs == 0 && dGetMessageHandler() == &onOdeMessage) {
    dSetMessageHandler(g_replaced.exchange(nullptr));
  }
}

MessageLog::Capture::Capture(MessageLog& log) : outer_(t_capturing) { t_capturing = &log; }
MessageLog::Capture::~Capture() { t_capturing = outer_; }

void MessageLog::add(int number, const char* format, std::va_list args) noexcept {
  ++total_;
  if (keep_ == Keep::kTotal) return;
  // ODE's formats are string literals: a message seen before is found by
  // its format's address, without allocating.
  for (std::size_t k = 0; k < formats_.size(); ++k) {
    if (formats_[k] == format && counts_[k].number == number) {
      ++counts_[k].count;
      return;
    }
  }
  try {
    const std::string text = messageText(format);
    for (std::size_t k = 0; k < counts_.size(); ++k) {
      if (counts_[k].number == number && counts_[k].text == text) {  // the same message from another literal
        ++counts_[k].count;
        return;
      }
    }
    char first[512];
    std::va_list copy;
    va_copy(copy, args);
    std::vsnprintf(first, sizeof first, format, copy);
    va_end(copy);
    formats_.reserve(formats_.size() + 1);
    counts_.push_back({.number = number, .text = text, .first = first, .count = 1});
    formats_.push_back(format);
  } catch (...) {
    // Out of memory inside ODE's step: the message stays in total() only.
  }
}

void MessageLog::merge(const MessageLog& other) {
  total_ += other.total_;
  for (std::size_t j = 0; j < other.counts_.size(); ++j) {
    const MessageCount& m = other.counts_[j];
    const auto same = std::find_if(counts_.begin(), counts_.end(),
                                   [&](const MessageCount& c) { return c.number == m.number && c.text == m.text; });
    if (same != counts_.end()) {
      same->count += m.count;
      continue;
    }
    formats_.reserve(formats_.size() + 1);
    counts_.push_back(m);
    formats_.push_back(other.formats_[j]);
  }
}

void MessageLog::clear() noexcept {
  counts_.clear();
  formats_.clear();
  total_ = 0;
}

std::string messageText(std::string_view format) {
  std::string text;
  for (std::size_t i = 0; i < format.size();) {
    if (format[i] == '(') {
      const std::size_t close = format.find(')', i);
      if (close != std::string_view::npos && format.substr(i, close - i).find('%') != std::string_view::npos) {
        while (!text.empty() && text.back() == ' ') text.pop_back();
        i = close + 1;
        continue;
      }
    }
    if (format[i] == '%') {
      if (i + 1 < format.size() && format[i + 1] == '%') {
        text += '%';
        i += 2;
      } else {
        text += "...";
        i += conversionLength(format, i);
      }
      continue;
    }
    text += format[i++];
  }
  return text;
}

}  // namespace wtc::ode
