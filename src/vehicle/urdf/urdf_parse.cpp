// urdfdom's parse, its logged errors captured (urdf_parse.hpp).
#include "urdf_parse.hpp"

#include <console_bridge/console.h>
#include <tinyxml.h>
#include <urdf_parser/urdf_parser.h>

#include "io/file_support.hpp"
#include "wtc/base/error.hpp"
#include "wtc/io/file_limits.hpp"

namespace wtc::vehicle::detail {
namespace {

// urdfdom reports through console_bridge and, for some faults (an
// <inertial> without <mass>), returns a model all the same: its errors are
// collected here and make the parse fail. Its info and warnings are kept
// off the terminal. Installed for one parse (console_bridge has one
// handler per process: not for concurrent parses).
class CapturedLog final : public console_bridge::OutputHandler {
 public:
  CapturedLog() { console_bridge::useOutputHandler(this); }
  ~CapturedLog() override { console_bridge::restorePreviousOutputHandler(); }
  CapturedLog(const CapturedLog&) = delete;
  CapturedLog& operator=(const CapturedLog&) = delete;

  void log(const std::string& text, console_bridge::LogLevel level, const char*, int) override {
    if (level >= console_bridge::CONSOLE_BRIDGE_LOG_ERROR) errors_ += (errors_.empty() ? "" : "; ") + text;
  }
  const std::string& errors() const { return errors_; }

 private:
  std::string errors_;
};

}  // namespace

ParsedUrdf parseUrdfFile(const std::filesystem::path& file) {
  const std::string xml = io::detail::readWholeFile(file, io::kMaxDescriptionFileBytes, "a URDF file");
  ParsedUrdf out;
  {
    CapturedLog log;
    out.model = urdf::parseURDF(xml);
    if (!out.model || !log.errors().empty()) {
      throw InvalidInputError(file.string() + ": urdfdom refuses it: " +
                              (log.errors().empty() ? std::string("not a valid URDF") : log.errors()));
    }
  }
  // urdfdom parsed the same text with TinyXML: it is well formed here.
  TiXmlDocument doc;
  doc.Parse(xml.c_str());
  const TiXmlElement* robot = doc.FirstChildElement("robot");
  for (const TiXmlElement* link = robot ? robot->FirstChildElement("link") : nullptr; link != nullptr;
       link = link->NextSiblingElement("link")) {
    if (const char* name = link->Attribute("name")) out.link_order.emplace_back(name);
  }
  return out;
}

}  // namespace wtc::vehicle::detail
