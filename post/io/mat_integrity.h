// SPDX-License-Identifier: GPL-2.0-or-later
// The structure of a MAT file checked before libmatio reads it: libmatio reads a variable cut
// by the end of the file with its missing part as zeros, and a compressed variable whose bytes
// were changed as whatever zlib made of them, without a word. scipy.io.loadmat refuses both;
// so does this check.
#ifndef OHMDEM_POST_MAT_INTEGRITY_H
#define OHMDEM_POST_MAT_INTEGRITY_H

#include <string>

namespace ohmdem::post {

// Throws Error naming the file, the variable and what is wrong when an element of a MAT v5
// file (or its compressed form) does not fit in the file (or in its decompressed stream), a
// compressed element does not decompress whole (zlib's status, its checksum), a numeric
// array's data do not hold its dimensions, or a MAT v4 matrix does not fit in the file.
// MAT v7.3 files (HDF5) are left to libmatio and HDF5.
void check_mat_integrity(const std::string &path);

}  // namespace ohmdem::post

#endif
