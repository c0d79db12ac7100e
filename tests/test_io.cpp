// Image decoding: formats read back as written, and the inputs the fuzzer found refused cleanly.
// Staged outputs: files appear under their names only when a run commits them.
#include <gtest/gtest.h>

#include <algorithm>
#include <filesystem>
#include <fstream>
#include <vector>
#include <visp3/io/vpImageIo.h>

#include "TestSupport.h"
#include "pm/core/Error.h"
#include "pm/io/ImageFile.h"
#include "pm/io/StagedFiles.h"

namespace {

vpImage<vpRGBa> pattern(unsigned h, unsigned w)
{
  vpImage<vpRGBa> I(h, w);
  for (unsigned v = 0; v < h; ++v)
    for (unsigned u = 0; u < w; ++u)
      I[v][u] = vpRGBa(static_cast<unsigned char>(37 * u), static_cast<unsigned char>(91 * v), static_cast<unsigned char>(u * v), 255);
  return I;
}

void writeBytes(const std::string &path, const std::string &bytes)
{
  std::ofstream(path, std::ios::binary) << bytes;
}

} // namespace

TEST(ImageFile, PngAndPpmReadBackExactlyPgmAsGrey)
{
  pm::test::TempDir d("io");
  const vpImage<vpRGBa> I = pattern(7, 11);
  pm::io::writeImage(I, d.file("a.png"));
  vpImageIo::write(I, d.file("a.ppm"));
  for (const char *name : {"a.png", "a.ppm"})
    EXPECT_TRUE(pm::io::readColorImage(d.file(name)) == I) << name;
  vpImage<unsigned char> G(3, 4);
  for (unsigned k = 0; k < G.getSize(); ++k)
    G.bitmap[k] = static_cast<unsigned char>(20 * k);
  vpImageIo::write(G, d.file("g.pgm"));
  const vpImage<vpRGBa> R = pm::io::readColorImage(d.file("g.pgm"));
  ASSERT_EQ(R.getSize(), G.getSize());
  for (unsigned k = 0; k < G.getSize(); ++k)
    EXPECT_EQ(R.bitmap[k].R, G.bitmap[k]) << k;
  // A PPM by its magic bytes, without an extension, with a comment in its header.
  writeBytes(d.file("noext"), std::string("P6\n# comment\n2 1\n255\n") + std::string("\x01\x02\x03\x04\x05\x06", 6));
  const vpImage<vpRGBa> P = pm::io::readColorImage(d.file("noext"));
  ASSERT_EQ(P.getWidth(), 2u);
  EXPECT_EQ(P[0][1].B, 6);
}

TEST(ImageFile, FuzzFindingsAreRefusedWithAnError)
{
  pm::test::TempDir d("io");
  // Each was a crash or a hang before (fuzz/regressions/image holds them too).
  const std::vector<std::pair<std::string, std::string>> bad{
      {"empty, no extension (ViSP threw std::out_of_range)", ""},
      {"a PPM claiming 10^10 pixels", "P6\n100000 100000\n255\n"},
      {"truncated PPM pixels", "P6\n4 4\n255\n\x01\x02"},
      {"a 16-bit PGM", "P5\n2 2\n65535\n12345678"},
      {"a PNG signature only", "\x89PNG\r\n\x1a\n"},
      {"a JPEG start only", "\xff\xd8\xff"},
      {"text", "hello"}};
  for (const auto &[what, bytes] : bad) {
    writeBytes(d.file("image"), bytes);
    EXPECT_THROW(pm::io::readColorImage(d.file("image")), pm::core::Error) << what;
  }
  // ViSP's reader hung on this one; it is a valid 8 x 6 PPM of maximum value 8 (the bytes
  // "2\n255\n" are its first pixels), read as such, each byte scaled by 255 / 8.
  writeBytes(d.file("image"), std::string("P6\n8 6\n8 2\n255\n") + std::string(138, '\x08'));
  const vpImage<vpRGBa> P = pm::io::readColorImage(d.file("image"));
  EXPECT_EQ(P.getWidth(), 8u);
  EXPECT_EQ(P.getHeight(), 6u);
  EXPECT_EQ(P[0][1].G, 255); // '5' (53) is over 8: clamped
  EXPECT_EQ(P[5][7].B, 255); // 8 of 8
  writeBytes(d.file("image"), std::string("P5 2 1 8 ") + std::string("\x02\x04", 2));
  const vpImage<vpRGBa> Q = pm::io::readColorImage(d.file("image"));
  EXPECT_EQ(Q[0][0].R, 64); // 2 of 8, rounded
  EXPECT_EQ(Q[0][1].R, 128);
}

namespace {
//! The names in \e dir, sorted.
std::vector<std::string> namesIn(const std::string &dir)
{
  std::vector<std::string> n;
  for (const auto &e : std::filesystem::directory_iterator(dir))
    n.push_back(e.path().filename().string());
  std::sort(n.begin(), n.end());
  return n;
}
} // namespace

TEST(StagedFiles, OutputsAppearOnlyOnCommitAndNothingIsLeftOtherwise)
{
  pm::test::TempDir d("staged");
  {
    // A run that fails after writing: its folder is made, but nothing is left in it.
    pm::io::StagedFiles out(d.file("failed/deeper"));
    const std::string tmp = out.stage("model.json");
    EXPECT_EQ(std::filesystem::path(tmp).extension(), ".json"); // writers that pick the format from it still work
    EXPECT_NE(tmp, out.finalPath("model.json"));
    std::ofstream(tmp) << "{ half";
    EXPECT_FALSE(std::filesystem::exists(out.finalPath("model.json")));
  }
  EXPECT_TRUE(namesIn(d.file("failed/deeper")).empty());
  {
    // A run that succeeds: every staged file under its final name, no temporary left.
    pm::io::StagedFiles out(d.file("ok"));
    std::ofstream(out.stage("a.txt")) << "first";
    std::ofstream(out.stage("b.png")) << "second";
    out.commit();
  }
  EXPECT_EQ(namesIn(d.file("ok")), (std::vector<std::string>{"a.txt", "b.png"}));
  EXPECT_EQ(pm::test::readText(d.file("ok/a.txt")), "first");
  {
    // A staged file that was never written: nothing is committed (not half a set of outputs),
    // and the error names the file.
    pm::io::StagedFiles out(d.file("missing"));
    std::ofstream(out.stage("written.txt")) << "x";
    (void)out.stage("never.txt");
    const std::string e = pm::test::errorOf([&] { out.commit(); });
    EXPECT_NE(e.find("never.txt"), std::string::npos) << e;
  }
  EXPECT_TRUE(namesIn(d.file("missing")).empty());
  // A folder that cannot be made is an error naming it.
  std::ofstream(d.file("file")) << "a file, not a folder";
  const std::string e = pm::test::errorOf([&] { pm::io::StagedFiles bad(d.file("file/sub")); });
  EXPECT_NE(e.find("file/sub"), std::string::npos) << e;
}

TEST(StagedFiles, WriteTextFileReplacesAWholeFileOrNothing)
{
  pm::test::TempDir d("staged");
  pm::io::writeTextFile(d.file("t.txt"), "one");
  pm::io::writeTextFile(d.file("t.txt"), "two");
  EXPECT_EQ(pm::test::readText(d.file("t.txt")), "two");
  EXPECT_EQ(namesIn(d.path()), (std::vector<std::string>{"t.txt"}));
  EXPECT_THROW(pm::io::writeTextFile(d.file("no/such/folder/t.txt"), "x"), pm::core::Error);
}
