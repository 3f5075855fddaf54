#pragma once
// ODE's messages, counted where they were printed and forgotten (wtc::ode).
// Design note:
//
// ODE says through dMessage that its solver gave up on part of a step and
// went on: dWorldStep's Dantzig LCP prints "LCP internal error, s <= 0
// (s=%.4e)" (ODE's lcp.cpp, message number d_ERR_LCP = 3) when a pivot
// finds no way forward, leaves the rows it had not solved without force
// and finishes the step. By default dMessage prints to stderr, where no
// summary sees it. A MessageLog counts such messages instead, by message,
// while a MessageLog::Capture of it is alive on the thread that steps.
//
// ODE keeps one message handler for the whole process (dSetMessageHandler).
// The first MessageLog installs WTC's, keeping the handler it replaces; the
// last one destroyed puts that one back (unless another has been installed
// over WTC's meanwhile: that one is left). WTC's handler gives a message to
// the log capturing on the calling thread, and any other message to the
// handler it replaced, or prints it as ODE would: code that captures
// nothing sees no change. A world steps on the calling thread with ODE's
// default threading or a self-threaded implementation (wtc::ode_sim gives
// each world one); with a thread pool of ODE's own, its messages come from
// the pool's threads and are not captured.
//
// ODE's error and debug handlers (dError: a user's bad argument; dDebug: a
// failed internal assertion) are left alone: ODE ends the process right
// after them (exit(1), abort()), so there is nothing to count, and ODE's own
// printing names the failure on the way out (wtc::study reports the last
// line of a crashed run's stderr).
#include <cstdarg>
#include <cstdint>
#include <string>
#include <string_view>
#include <vector>

namespace wtc::ode {

/// One message, as often as it came.
struct MessageCount {
  int number = 0;           ///< ODE's message number (d_ERR_LCP = 3 for the LCP's).
  std::string text;         ///< The message without its numbers (messageText): "LCP internal error, s <= 0".
  std::string first;        ///< The first in full: "LCP internal error, s <= 0 (s=0.0000e+00)".
  std::uint64_t count = 0;  ///< Times it came.
};

class MessageLog {
 public:
  /// What a log keeps of the messages it counts.
  enum class Keep {
    kMessages,  ///< each message's text and count (counts())
    kTotal,     ///< their total alone: never allocates (a solve tried only to see whether ODE gave up)
  };

  /// Installs WTC's message handler if no other log has (thread-safe).
  explicit MessageLog(Keep keep = Keep::kMessages);
  /// Puts back the handler WTC's replaced when it is the last log.
  ~MessageLog();
  MessageLog(const MessageLog&) = delete;
  MessageLog& operator=(const MessageLog&) = delete;

  /// While alive, ODE's messages made on this thread are counted in `log`
  /// instead of printed. Captures nest (the innermost counts); destroy on
  /// the thread that made it, before the log.
  class Capture {
   public:
    explicit Capture(MessageLog& log);
    ~Capture();
    Capture(const Capture&) = delete;
    Capture& operator=(const Capture&) = delete;

   private:
    MessageLog* outer_;
  };

  /// By message, in the order each first came.
  const std::vector<MessageCount>& counts() const { return counts_; }
  /// Messages counted so far, all kinds together.
  std::uint64_t total() const { return total_; }

  /// Counts one message (WTC's handler calls it). Allocates only for a
  /// message not seen before; never throws (a message it cannot store is
  /// still counted in total()).
  void add(int number, const char* format, std::va_list args) noexcept;

  /// Counts `other`'s messages here too, as if they had come here (a solve
  /// tried in a log of its own and then kept: wtc::ode_sim's direct step).
  void merge(const MessageLog& other);
  /// Forgets every message (a solve tried and dropped).
  void clear() noexcept;

 private:
  std::vector<MessageCount> counts_;
  std::vector<const char*> formats_;  // counts_[k]'s first format, to find it again without allocating
  std::uint64_t total_ = 0;
  Keep keep_;
};

/// ODE's message format without its numbers: each parenthesised part that
/// holds a conversion left out with the space before it, any other
/// conversion written "...", "%%" as "%". "LCP internal error, s <= 0
/// (s=%.4e)" -> "LCP internal error, s <= 0".
std::string messageText(std::string_view format);

}  // namespace wtc::ode
