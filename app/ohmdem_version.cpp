// SPDX-License-Identifier: GPL-2.0-or-later
// The project version, one definition for the engine and the post tool.
namespace ohmdem {
const char *version()
{
  return OHMDEM_VERSION;
}
}  // namespace ohmdem
