#include "sheet/SheetFiles.h"

#include "sheet/SheetHtml.h"
#include "sheet/SheetPicture.h"

#include "base/AtomicFile.h"

#include <QPageLayout>
#include <QPageSize>
#include <QPdfWriter>
#include <QString>
#include <QTextDocument>
#include <QUrl>

#include <filesystem>
#include <system_error>
#include <unistd.h>
#include <utility>
#include <vector>

namespace camwb::sheet {

namespace fs = std::filesystem;

namespace {

constexpr double kPdfPictureScale = 0.6;

// The pictures as the HTML names them ("<stem>-images/op-1.png") with their images.
struct Pictures {
    SheetImages names;
    std::vector<std::pair<std::string, QImage>> images;
};

Pictures drawPictures(const document::SetupSheet& sheet, const SheetPicture& renderer, const SheetOutput& output,
                      const std::string& folder)
{
    Pictures out;
    const auto add = [&](const std::string& file, QImage image) {
        const std::string name = folder + "/" + file;
        out.images.emplace_back(name, image);
        return SheetImage{name, image.width(), image.height()};
    };
    out.names.part =
        add("part.png", output.partPicture ? *output.partPicture : renderer.render(QSize(kPartWidth, kPartHeight)));
    for (std::size_t i = 0; i < sheet.operations.size(); ++i)
        out.names.operations.push_back(
            add("op-" + std::to_string(i + 1) + ".png",
                renderer.render(QSize(kOperationWidth, kOperationHeight), static_cast<int>(i))));
    return out;
}

// The same sheet as the HTML, its pictures shown smaller so that two fit on a landscape page.
base::Status writePdf(const document::SetupSheet& sheet, const Pictures& pictures, const std::string& path)
{
    SheetImages printed = pictures.names;
    const auto shrink = [](SheetImage& image) {
        image.width = static_cast<int>(image.width * kPdfPictureScale);
        image.height = static_cast<int>(image.height * kPdfPictureScale);
    };
    shrink(printed.part);
    for (SheetImage& image : printed.operations)
        shrink(image);
    QTextDocument document;
    for (const auto& [name, image] : pictures.images)
        document.addResource(QTextDocument::ImageResource, QUrl(QString::fromStdString(name)), image);
    document.setHtml(QString::fromStdString(sheetHtml(sheet, printed)));
    QPdfWriter writer(QString::fromStdString(path));
    writer.setTitle(QString::fromStdString("Setup sheet: " + sheet.jobName));
    writer.setCreator(QStringLiteral("CAM Workbench"));
    writer.setPageLayout(QPageLayout(QPageSize(QPageSize::A4), QPageLayout::Landscape, QMarginsF(12, 12, 12, 12),
                                     QPageLayout::Millimeter));
    document.print(&writer);
    std::error_code ec;
    if (!fs::exists(path, ec) || fs::file_size(path, ec) == 0)
        return base::makeError("cannot write the PDF '" + path + "'");
    return {};
}

base::Status renamed(const fs::path& from, const fs::path& to)
{
    std::error_code ec;
    fs::rename(from, to, ec);
    if (ec)
        return base::makeError("cannot move '" + from.string() + "' to '" + to.string() + "': " + ec.message());
    return {};
}

}  // namespace

base::Status writeSetupSheet(const document::SetupSheet& sheet, const SheetPicture& renderer, const SheetOutput& output)
{
    const fs::path html = fs::absolute(output.htmlPath);
    const std::string folder = html.stem().string() + "-images";
    const fs::path temp = html.parent_path() / ("." + html.filename().string() + ".tmp-" + std::to_string(::getpid()));
    const fs::path tempPdf =
        output.pdfPath.empty() ? fs::path() : fs::path(output.pdfPath + ".tmp-" + std::to_string(::getpid()));
    std::error_code ec;
    fs::remove_all(temp, ec);
    if (!fs::create_directories(temp / folder, ec) || ec)
        return base::makeError("cannot create '" + (temp / folder).string() + "': " + ec.message());
    const auto cleanUp = [&] {
        std::error_code ignored;
        fs::remove_all(temp, ignored);
        if (!tempPdf.empty())
            fs::remove(tempPdf, ignored);
    };

    const Pictures pictures = drawPictures(sheet, renderer, output, folder);
    for (const auto& [name, image] : pictures.images) {
        if (!image.save(QString::fromStdString((temp / name).string()), "PNG")) {
            cleanUp();
            return base::makeError("cannot write the picture '" + (temp / name).string() + "'");
        }
    }
    const std::string text = sheetHtml(sheet, pictures.names);
    base::Status status = base::writeFileAtomically((temp / html.filename()).string(), text);
    if (status && !tempPdf.empty())
        status = writePdf(sheet, pictures, tempPdf.string());
    if (!status) {
        cleanUp();
        return status;
    }

    // Everything is written: replace the old sheet's pictures, then the HTML and the PDF.
    fs::remove_all(html.parent_path() / folder, ec);
    status = renamed(temp / folder, html.parent_path() / folder);
    if (status)
        status = renamed(temp / html.filename(), html);
    if (status && !tempPdf.empty())
        status = renamed(tempPdf, output.pdfPath);
    cleanUp();
    return status;
}

}  // namespace camwb::sheet
