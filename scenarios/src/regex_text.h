// std::regex helpers shared by the sources that read narrative text.
#pragma once

#include <functional>
#include <regex>
#include <string>

namespace accsim::regex_text {

inline bool Has(const std::string& s, const std::regex& re) { return std::regex_search(s, re); }

// regex_replace with a callback (std::regex has none).
inline std::string ReplaceWith(const std::string& s, const std::regex& re,
                               const std::function<std::string(const std::smatch&)>& fn) {
  std::string out;
  auto begin = s.cbegin();
  for (auto it = std::sregex_iterator(s.begin(), s.end(), re); it != std::sregex_iterator(); ++it) {
    out.append(begin, (*it)[0].first);
    out += fn(*it);
    begin = (*it)[0].second;
  }
  out.append(begin, s.cend());
  return out;
}

}  // namespace accsim::regex_text
