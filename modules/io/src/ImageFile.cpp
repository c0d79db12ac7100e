#include "pm/io/ImageFile.h"

#include <algorithm>
#include <cctype>
#include <csetjmp>
#include <cstdio>
#include <cstring>
#include <filesystem>
#include <fstream>
#include <limits>
#include <memory>
#include <vector>

#include <jpeglib.h>
#include <png.h>
#include <visp3/core/vpException.h>
#include <visp3/io/vpImageIo.h>

#include "pm/core/Error.h"

namespace pm::io {

namespace {

//! Larger images are refused: 100 Mpx, 400 MB as vpRGBa (a camera's frame is a few Mpx).
constexpr double kMaxPixels = 1e8;

std::string lowerExtension(const std::string &path)
{
  std::string e = std::filesystem::path(path).extension().string();
  std::transform(e.begin(), e.end(), e.begin(), [](unsigned char c) { return static_cast<char>(std::tolower(c)); });
  return e;
}

bool startsWith(const std::string &path, const unsigned char *magic, std::size_t n)
{
  unsigned char buf[8] = {0};
  std::unique_ptr<FILE, int (*)(FILE *)> f(std::fopen(path.c_str(), "rb"), &std::fclose);
  return f && std::fread(buf, 1, n, f.get()) == n && std::memcmp(buf, magic, n) == 0;
}

// PNG through libpng's simplified API: errors come back as text, nothing is printed, a
// truncated file is an error (not a half-decoded image).
vpImage<vpRGBa> readPng(const std::string &path)
{
  png_image img;
  std::memset(&img, 0, sizeof img);
  img.version = PNG_IMAGE_VERSION;
  if (!png_image_begin_read_from_file(&img, path.c_str()))
    throw core::Error("cannot read image '" + path + "': not a valid PNG (" + img.message + ")");
  img.format = PNG_FORMAT_RGBA;
  if (img.width == 0 || img.height == 0 || static_cast<double>(img.width) * img.height > kMaxPixels) {
    png_image_free(&img);
    throw core::Error("cannot read image '" + path + "': unreasonable size " + std::to_string(img.width) + "x" +
                std::to_string(img.height));
  }
  vpImage<vpRGBa> I(img.height, img.width);
  if (!png_image_finish_read(&img, nullptr, I.bitmap, 0, nullptr))
    throw core::Error("cannot read image '" + path + "': corrupt or truncated PNG (" + img.message + ")");
  return I;
}

struct JpegError
{
  jpeg_error_mgr mgr;
  std::jmp_buf jump;
  char message[JMSG_LENGTH_MAX];
};

void jpegErrorExit(j_common_ptr c)
{
  JpegError *e = reinterpret_cast<JpegError *>(c->err);
  (*c->err->format_message)(c, e->message);
  std::longjmp(e->jump, 1);
}

void jpegOutputMessage(j_common_ptr c)
{
  JpegError *e = reinterpret_cast<JpegError *>(c->err);
  (*c->err->format_message)(c, e->message); // keep the warning (e.g. premature end) for our report
}

// JPEG through libjpeg with an error manager that reports instead of printing or exiting;
// a warning (premature end of data, corrupt data) makes the file unreadable.
vpImage<vpRGBa> readJpeg(const std::string &path)
{
  std::unique_ptr<FILE, int (*)(FILE *)> f(std::fopen(path.c_str(), "rb"), &std::fclose);
  if (!f)
    throw core::Error("cannot open image '" + path + "'");
  jpeg_decompress_struct cinfo;
  JpegError err;
  err.message[0] = 0;
  cinfo.err = jpeg_std_error(&err.mgr);
  err.mgr.error_exit = jpegErrorExit;
  err.mgr.output_message = jpegOutputMessage;
  std::vector<unsigned char> row;
  vpImage<vpRGBa> I;
  if (setjmp(err.jump)) {
    jpeg_destroy_decompress(&cinfo);
    throw core::Error("cannot read image '" + path + "': not a valid JPEG (" + err.message + ")");
  }
  jpeg_create_decompress(&cinfo);
  jpeg_stdio_src(&cinfo, f.get());
  jpeg_read_header(&cinfo, TRUE);
  if (static_cast<double>(cinfo.image_width) * cinfo.image_height > kMaxPixels) {
    jpeg_destroy_decompress(&cinfo);
    throw core::Error("cannot read image '" + path + "': unreasonable size " + std::to_string(cinfo.image_width) + "x" +
                std::to_string(cinfo.image_height));
  }
  cinfo.out_color_space = JCS_RGB;
  jpeg_start_decompress(&cinfo);
  if (static_cast<double>(cinfo.output_width) * cinfo.output_height > kMaxPixels || cinfo.output_components != 3) {
    jpeg_destroy_decompress(&cinfo);
    throw core::Error("cannot read image '" + path + "': unsupported JPEG");
  }
  I.resize(cinfo.output_height, cinfo.output_width);
  row.resize(3 * static_cast<std::size_t>(cinfo.output_width));
  while (cinfo.output_scanline < cinfo.output_height) {
    JSAMPROW r = row.data();
    const unsigned v = cinfo.output_scanline;
    jpeg_read_scanlines(&cinfo, &r, 1);
    for (unsigned u = 0; u < cinfo.output_width; ++u)
      I[v][u] = vpRGBa(row[3 * u], row[3 * u + 1], row[3 * u + 2], 255);
  }
  jpeg_finish_decompress(&cinfo);
  const long warnings = cinfo.err->num_warnings;
  jpeg_destroy_decompress(&cinfo);
  if (warnings > 0)
    throw core::Error("cannot read image '" + path + "': corrupt or truncated JPEG (" + err.message + ")");
  return I;
}

/*!
  Binary PGM (P5) and PPM (P6), 8 bits. Ours rather than ViSP's: vpImageIo::readPPM hangs on
  some malformed headers, and picks the format from the file name (it throws std::out_of_range
  on a name without an extension). Found by fuzz/fuzz_image.
*/
vpImage<vpRGBa> readPnm(const std::string &path)
{
  std::ifstream f(path, std::ios::binary);
  std::string magic;
  f >> magic;
  if (magic != "P5" && magic != "P6")
    throw core::Error("cannot read image '" + path + "': not a PNG, JPEG or binary PGM/PPM image");
  long header[3] = {0, 0, 0}; // width, height, maximum value
  for (long &v : header) {
    while (f >> std::ws && f.peek() == '#') // comments
      f.ignore(std::numeric_limits<std::streamsize>::max(), '\n');
    if (!(f >> v))
      throw core::Error("cannot read image '" + path + "': truncated " + magic + " header");
  }
  const long w = header[0], h = header[1];
  if (w <= 0 || h <= 0 || static_cast<double>(w) * static_cast<double>(h) > kMaxPixels)
    throw core::Error("cannot read image '" + path + "': bad or unreasonable size " + std::to_string(w) + "x" + std::to_string(h));
  if (header[2] < 1 || header[2] > 255)
    throw core::Error("cannot read image '" + path + "': only 8-bit PGM/PPM are read (maximum value " + std::to_string(header[2]) + ")");
  if (!std::isspace(f.get())) // one whitespace, then the pixels
    throw core::Error("cannot read image '" + path + "': malformed " + magic + " header");
  const std::size_t channels = magic == "P6" ? 3 : 1;
  std::vector<unsigned char> row(channels * static_cast<std::size_t>(w));
  vpImage<vpRGBa> I(static_cast<unsigned>(h), static_cast<unsigned>(w));
  for (unsigned v = 0; v < I.getHeight(); ++v) {
    if (!f.read(reinterpret_cast<char *>(row.data()), static_cast<std::streamsize>(row.size())))
      throw core::Error("cannot read image '" + path + "': truncated " + magic + " pixels");
    for (auto &c : row) // onto 0..255, whatever the maximum value
      c = static_cast<unsigned char>(std::min<long>(255, (255 * static_cast<long>(c) + header[2] / 2) / header[2]));
    for (unsigned u = 0; u < I.getWidth(); ++u) {
      const unsigned char *p = &row[channels * u];
      I[v][u] = channels == 3 ? vpRGBa(p[0], p[1], p[2], 255) : vpRGBa(p[0], p[0], p[0], 255);
    }
  }
  return I;
}

} // namespace

vpImage<vpRGBa> readColorImage(const std::string &path)
{
  std::error_code ec;
  if (!std::filesystem::is_regular_file(path, ec))
    throw core::Error("image '" + path + "' does not exist or is not a file");
  static const unsigned char pngMagic[8] = {0x89, 'P', 'N', 'G', '\r', '\n', 0x1a, '\n'};
  static const unsigned char jpegMagic[3] = {0xff, 0xd8, 0xff};
  const std::string ext = lowerExtension(path);
  if (startsWith(path, pngMagic, 8) || ext == ".png")
    return readPng(path);
  if (startsWith(path, jpegMagic, 3) || ext == ".jpg" || ext == ".jpeg")
    return readJpeg(path);
  return readPnm(path);
}

namespace {
template <typename T> void writeAny(const vpImage<T> &I, const std::string &path)
{
  try {
    vpImageIo::write(I, path);
  } catch (const vpException &e) {
    throw core::Error("cannot write image '" + path + "': " + e.getStringMessage());
  }
}
} // namespace

void writeImage(const vpImage<vpRGBa> &I, const std::string &path) { writeAny(I, path); }
void writeImage(const vpImage<unsigned char> &I, const std::string &path) { writeAny(I, path); }

} // namespace pm::io
