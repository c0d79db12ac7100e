#pragma once
/*!
  \file ImageFile.h
  Image reading and writing with errors a user can act on (pm::core::Error naming the file).
  Reading decodes PNG (libpng), JPEG (libjpeg) and 8-bit binary PGM/PPM here; writing goes
  through ViSP's vpImageIo (whatever formats it was built with, picked by the extension).
*/
#include <string>

#include <visp3/core/vpImage.h>
#include <visp3/core/vpRGBa.h>

namespace pm::io {

//! Reads a colour image: PNG, JPEG (by their magic bytes or extension), binary PGM/PPM. Throws
//! pm::core::Error if the file is missing, unreadable, corrupt, empty or over 100 Mpx.
vpImage<vpRGBa> readColorImage(const std::string &path);
//! Writes a colour image; the format follows the extension. Throws pm::core::Error.
void writeImage(const vpImage<vpRGBa> &I, const std::string &path);
//! Writes a grey-level image; the format follows the extension. Throws pm::core::Error.
void writeImage(const vpImage<unsigned char> &I, const std::string &path);

} // namespace pm::io
