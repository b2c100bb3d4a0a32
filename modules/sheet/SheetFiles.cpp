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

#include <atomic>
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
base::Status writePdf(const document::SetupSheet& sheet, const Pictures& pictures, SheetUnit unit,
                      const std::string& path)
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
    document.setHtml(QString::fromStdString(sheetHtml(sheet, printed, unit)));
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

StagedSheet::StagedSheet(StagedSheet&& other) noexcept :
    m_output(std::move(other.m_output)),
    m_temp(std::move(other.m_temp)),
    m_tempPdf(std::move(other.m_tempPdf)),
    m_folder(std::move(other.m_folder)),
    m_done(other.m_done)
{
    other.m_done = true;  // the temporaries are this one's now
}

StagedSheet::~StagedSheet()
{
    if (!m_done)
        removeTemporaries();
}

void StagedSheet::removeTemporaries()
{
    std::error_code ignored;
    fs::remove_all(m_temp, ignored);
    if (!m_tempPdf.empty())
        fs::remove(m_tempPdf, ignored);
}

base::Status StagedSheet::commit()
{
    if (m_done)
        return base::makeError("the setup sheet was committed or discarded already");
    m_done = true;
    const fs::path html = fs::absolute(m_output.htmlPath);
    const fs::path temp(m_temp);
    std::error_code ec;
    fs::remove_all(html.parent_path() / m_folder, ec);
    base::Status status = renamed(temp / m_folder, html.parent_path() / m_folder);
    if (status)
        status = renamed(temp / html.filename(), html);
    if (status && !m_tempPdf.empty())
        status = renamed(m_tempPdf, m_output.pdfPath);
    removeTemporaries();
    return status;
}

base::Result<StagedSheet> stageSetupSheet(const document::SetupSheet& sheet, const SheetPicture& renderer,
                                          const SheetOutput& output)
{
    // Unique per staging (a process may stage two sheets for one place: the later one wins).
    static std::atomic<unsigned> counter{0};
    const std::string unique = std::to_string(::getpid()) + "-" + std::to_string(counter++);
    const fs::path html = fs::absolute(output.htmlPath);
    StagedSheet staged;
    staged.m_output = output;
    staged.m_folder = html.stem().string() + "-images";
    staged.m_temp = (html.parent_path() / ("." + html.filename().string() + ".tmp-" + unique)).string();
    if (!output.pdfPath.empty())
        staged.m_tempPdf = output.pdfPath + ".tmp-" + unique;
    const fs::path temp(staged.m_temp);
    std::error_code ec;
    if (!fs::create_directories(temp / staged.m_folder, ec) || ec)
        return base::makeError("cannot create '" + (temp / staged.m_folder).string() + "': " + ec.message());

    const Pictures pictures = drawPictures(sheet, renderer, output, staged.m_folder);
    for (const auto& [name, image] : pictures.images)
        if (!image.save(QString::fromStdString((temp / name).string()), "PNG"))
            return base::makeError("cannot write the picture '" + (temp / name).string() + "'");
    const std::string text = sheetHtml(sheet, pictures.names, output.unit);
    base::Status status = base::writeFileAtomically((temp / html.filename()).string(), text);
    if (status && !staged.m_tempPdf.empty())
        status = writePdf(sheet, pictures, output.unit, staged.m_tempPdf);
    if (!status)
        return status.error();  // the temporaries go with `staged`
    return staged;
}

base::Status writeSetupSheet(const document::SetupSheet& sheet, const SheetPicture& renderer, const SheetOutput& output)
{
    auto staged = stageSetupSheet(sheet, renderer, output);
    if (!staged)
        return staged.error();
    return staged.value().commit();
}

}  // namespace camwb::sheet
