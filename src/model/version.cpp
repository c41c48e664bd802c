#include "capsubot/model/version.hpp"

namespace capsubot {

const char* Version() { return CAPSUBOT_VERSION; }

}  // namespace capsubot
