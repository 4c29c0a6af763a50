// SPDX-License-Identifier: BSD-3-Clause
/**
 * @file vtkMedialJson.h
 * @brief Internal: JSON string literals, written in one place for the CLI's `--stats` line
 * and the HTML page's manifest.
 *
 * vtkMedialJsonString() quotes a string and escapes what JSON requires (quote, backslash,
 * control characters). With scriptSafe it also escapes `<`, `>` and `&` as \\u003c,
 * \\u003e and \\u0026, so that the literal can sit inside an HTML `<script>` element without
 * ending it ("</script>") or opening a comment ("<!--"); JSON readers decode both forms to
 * the same text. Header only; not installed.
 */
#ifndef vtkMedialJson_h
#define vtkMedialJson_h

#include <cstdio>
#include <string>

inline std::string vtkMedialJsonString(const std::string& s, bool scriptSafe = false)
{
  std::string out = "\"";
  for (const char c : s)
  {
    const bool scriptSpecial = c == '<' || c == '>' || c == '&';
    if (c == '"' || c == '\\')
    {
      out += '\\';
      out += c;
    }
    else if (c == '\n')
    {
      out += "\\n";
    }
    else if (static_cast<unsigned char>(c) < 0x20 || (scriptSafe && scriptSpecial))
    {
      char buf[8];
      std::snprintf(buf, sizeof(buf), "\\u%04x", static_cast<unsigned>(static_cast<unsigned char>(c)));
      out += buf;
    }
    else
    {
      out += c;
    }
  }
  return out + "\"";
}

#endif
