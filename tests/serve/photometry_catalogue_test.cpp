// The studio's photometry catalogue (serve/photometry_catalogue.h): every IES/LDT file under
// the folder listed with its summary and a polar plot exact to the file's own web (I = 1000 cos γ
// gives 500 cd at 60° within 1e-9 relative), files the parsers refuse listed with their message;
// uploads stored under server-chosen names in the catalogue's uploads/ folder, and refused —
// with nothing written — for a path as a name, another extension, more than 5 MB, binary data
// or a truncated file.
#include <gtest/gtest.h>

#include <cmath>
#include <filesystem>
#include <sstream>
#include <string>

#include "common/input_error.h"
#include "serve/photometry_catalogue.h"
#include "support/temp_dir.h"

namespace relight {
namespace {

namespace fs = std::filesystem;

// An LM-63-2002 file of I(γ) = 1000 cos γ on [0°, 90°] every 5°, 20 W.
std::string cosine_ies() {
  std::ostringstream s;
  s << "IESNA:LM-63-2002\n[MANUFAC] Acme\n[LUMINAIRE] Cosine\nTILT=NONE\n";
  s << "1 -1 1 19 1 1 2 0.2 0.2 0\n1 1 20\n";
  for (int g = 0; g <= 90; g += 5) s << g << " ";
  s << "\n0\n";
  for (int g = 0; g <= 90; g += 5) s << 1000.0 * std::cos(g * M_PI / 180.0) << " ";
  s << "\n";
  return s.str();
}

std::string message_of(const std::function<void()>& f) {
  try {
    f();
  } catch (const InputError& e) {
    return e.what();
  }
  return "(no error)";
}

std::size_t files_in(const fs::path& folder) {
  if (!fs::exists(folder)) return 0;
  return static_cast<std::size_t>(
      std::distance(fs::directory_iterator(folder), fs::directory_iterator()));
}

TEST(PhotometryCatalogue, ListsEveryPhotometricFileWithItsSummaryPolarPlotAndRefusals) {
  const testing::TempDir dir;
  dir.write("b.ies", cosine_ies());
  fs::create_directories(dir.path() / "sub");
  dir.write("sub/a.IES", cosine_ies());
  dir.write("truncated.ies", cosine_ies().substr(0, 60));
  dir.write("notes.txt", "not photometry");
  const PhotometryCatalogue catalogue(dir.path());
  ASSERT_EQ(catalogue.entries().size(), 2u);
  EXPECT_EQ(catalogue.entries()[0].id, "b.ies");
  EXPECT_EQ(catalogue.entries()[1].id, "sub/a.IES");
  EXPECT_TRUE(catalogue.entries()[1].file.is_absolute());
  ASSERT_EQ(catalogue.rejected().size(), 1u);
  EXPECT_EQ(catalogue.rejected()[0].id, "truncated.ies");
  EXPECT_NE(catalogue.rejected()[0].message.find("truncated.ies"), std::string::npos);

  const nlohmann::json entry = catalogue_entry_json(catalogue.entries()[0]);
  EXPECT_EQ(entry.at("type"), "ies");
  EXPECT_EQ(entry.at("summary").at("manufacturer"), "Acme");
  EXPECT_EQ(entry.at("summary").at("watts"), 20.0);
  const nlohmann::json& polar = entry.at("polar");
  ASSERT_EQ(polar.at("gamma_deg").size(), 37u);
  EXPECT_EQ(polar.at("gamma_deg")[12], 60);
  EXPECT_NEAR(polar.at("c0")[12].get<double>(), 500.0, 500.0 * 1e-9);
  EXPECT_NEAR(polar.at("c270")[0].get<double>(), 1000.0, 1000.0 * 1e-9);
  EXPECT_EQ(polar.at("c90")[36].get<double>(), 0.0);
  EXPECT_EQ(catalogue_message(catalogue).at("entries").size(), 2u);
}

TEST(PhotometryCatalogue, AnUploadIsParsedAndStoredUnderANameTheServerChooses) {
  const testing::TempDir dir;
  PhotometryCatalogue catalogue(dir.path());
  const std::string text = cosine_ies();
  const CatalogueEntry first = catalogue.add_upload("My downlight.IES", text);
  const CatalogueEntry second = catalogue.add_upload("My downlight.IES", text);
  EXPECT_EQ(first.file, dir.path() / "uploads" / "upload-1.ies");
  EXPECT_EQ(second.file, dir.path() / "uploads" / "upload-2.ies");
  EXPECT_TRUE(first.uploaded);
  EXPECT_EQ(testing::read_text(first.file), text);
  EXPECT_EQ(catalogue_entry_json(first).at("name"), "My downlight.IES");
  EXPECT_EQ(catalogue.entries().size(), 2u);
  // A new catalogue of the folder lists the uploads again.
  EXPECT_EQ(PhotometryCatalogue(dir.path()).entries().size(), 2u);
}

TEST(PhotometryCatalogue, BadUploadsAreRefusedWithAClearMessageAndNothingIsWritten) {
  const testing::TempDir dir;
  PhotometryCatalogue catalogue(dir.path());
  const std::string text = cosine_ies();
  EXPECT_NE(message_of([&] {
              catalogue.add_upload("../../etc/lamp.ies", text);
            }).find("message:/name: expected a plain file name, not a path"),
            std::string::npos);
  EXPECT_NE(message_of([&] { catalogue.add_upload("..\\lamp.ies", text); }).find("not a path"),
            std::string::npos);
  EXPECT_NE(message_of([&] { catalogue.add_upload("lamp.txt", text); }).find("must end in .ies"),
            std::string::npos);
  std::string oversized = text;
  oversized.resize(kMaxUploadBytes + 1, ' ');
  EXPECT_NE(message_of([&] {
              catalogue.add_upload("big.ies", oversized);
            }).find("over the upload limit of 5 MB"),
            std::string::npos);
  std::string binary = text;
  binary[40] = '\0';
  EXPECT_NE(message_of([&] {
              catalogue.add_upload("bin.ies", binary);
            }).find("message:/text: bin.ies: binary data at byte 40"),
            std::string::npos);
  const std::string truncated =
      message_of([&] { catalogue.add_upload("cut.ies", text.substr(0, 80)); });
  EXPECT_EQ(truncated.rfind("cut.ies:", 0), 0u) << truncated;  // the parser's FILE:LINE message
  EXPECT_EQ(files_in(dir.path() / "uploads"), 0u);
  EXPECT_TRUE(catalogue.entries().empty());
}

TEST(PhotometryCatalogue, AFolderThatIsNotThereIsAnInputError) {
  EXPECT_NE(message_of([] { PhotometryCatalogue("/nonexistent/photometry"); }).find("not a folder"),
            std::string::npos);
}

}  // namespace
}  // namespace relight
