// SPDX-License-Identifier: GPL-2.0-or-later
// ohmdem-post: the post-processing command line (commands in commands.cpp).
#include "cli/commands.h"

int main(int argc, char **argv)
{
  return ohmdem::post::cli::dispatch(argc, argv);
}
