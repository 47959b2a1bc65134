#include "exportmapdialog.h"

#include "common/lastfolder.h"

#include "scanform.h"

#include "inference/blocksampler.h"
#include "mapexport/mapexportformat.h"
#include "mapexport/mapverifier.h"
#include "profile/profileloader.h"

#include <QtCore/QDir>
#include <QtCore/QSaveFile>
#include <QtWidgets/QComboBox>
#include <QtWidgets/QDialogButtonBox>
#include <QtWidgets/QFileDialog>
#include <QtWidgets/QFormLayout>
#include <QtWidgets/QHBoxLayout>
#include <QtWidgets/QLabel>
#include <QtWidgets/QLineEdit>
#include <QtWidgets/QPushButton>
#include <QtWidgets/QSpinBox>
#include <QtWidgets/QVBoxLayout>

#include <algorithm>

namespace mbscope {

namespace {

// One read of every block through url, a unit at a time: what MapVerifier judges.
QList<ExportBlockReading> readBlocks(BlockSampler *sampler, const LinkUrl &url, int timeoutMs, const QList<MapPoint> &points,
                                     const QList<ExportBlock> &blocks)
{
    QList<ExportBlockReading> readings(blocks.size());
    QList<quint8> units;
    for (const ExportBlock &b : blocks) {
        if (!units.contains(b.unitId))
            units.append(b.unitId);
    }
    for (const quint8 unit : std::as_const(units)) {
        SampleSettings s;
        s.url = url;
        s.unit = unit;
        s.samples = 1;
        s.intervalMs = 0;
        s.timeoutMs = timeoutMs;
        s.maxQuantity = 2000; // the blocks are already cut to the device's limits
        QList<qsizetype> which;
        for (qsizetype i = 0; i < blocks.size(); ++i) {
            const ExportBlock &b = blocks.at(i);
            if (b.unitId != unit)
                continue;
            which.append(i);
            s.blocks.append(BlockRequest{points.at(b.points.constFirst()).readFunction(), b.start, b.quantity});
        }
        const QList<BlockSamples> read = sampler->run(s);
        for (qsizetype k = 0; k < which.size(); ++k) {
            ExportBlockReading &r = readings[which.at(k)];
            if (k < read.size() && !read.at(k).samples.isEmpty())
                r.words = read.at(k).samples.constFirst();
            else
                r.error = sampler->problem().isEmpty() ? ExportMapDialog::tr("no usable answer") : sampler->problem();
        }
    }
    return readings;
}

} // namespace

ExportMapDialog::ExportMapDialog(QWidget *parent)
    : QDialog(parent)
    , m_profile(new QLineEdit(this))
    , m_format(new QComboBox(this))
    , m_endpoint(new QLineEdit(this))
    , m_interval(ScanForm::spinBox(this, "exportInterval", 1, 86400000, 1000, tr(" ms")))
    , m_verify(new QLineEdit(this))
    , m_output(new QLineEdit(this))
    , m_export(new QPushButton(tr("&Export"), this))
    , m_status(new QLabel(this))
    , m_sampler(new BlockSampler(this))
{
    setWindowTitle(tr("Export map"));
    m_profile->setObjectName(QStringLiteral("exportProfile"));
    m_profile->setPlaceholderText(tr("a shipped profile's name or a JSON file"));
    m_format->setObjectName(QStringLiteral("exportFormat"));
    for (const MapExportFormat f : {MapExportFormat::NodeRed, MapExportFormat::Telegraf, MapExportFormat::HomeAssistant,
                                    MapExportFormat::ModbusExporter, MapExportFormat::Csv})
        m_format->addItem(MapExporter::formatName(f), int(f));
    m_endpoint->setObjectName(QStringLiteral("exportEndpoint"));
    m_endpoint->setPlaceholderText(tr("the profile's first endpoint the format takes"));
    m_endpoint->setToolTip(tr("Where the tool will reach the device: tcp://host:port, rtu-tcp://..., rtu:///dev/ttyUSB0?baud=..."));
    m_interval->setToolTip(tr("How often the tool polls."));
    m_verify->setObjectName(QStringLiteral("exportVerify"));
    m_verify->setPlaceholderText(tr("empty: export without reading"));
    m_verify->setToolTip(tr("Read every value once from this target first and refuse the export when one is not finite "
                            "or outside the min and max its entry declares."));
    m_output->setObjectName(QStringLiteral("exportOutput"));
    m_export->setObjectName(QStringLiteral("exportRun"));
    m_status->setObjectName(QStringLiteral("exportStatus"));
    m_status->setWordWrap(true);
    m_status->setTextInteractionFlags(Qt::TextSelectableByMouse);

    auto *browseProfile = new QPushButton(tr("&Browse\u2026"), this);
    auto *browseOutput = new QPushButton(tr("Ch&oose\u2026"), this);
    auto *profileRow = new QHBoxLayout;
    profileRow->addWidget(m_profile, 1);
    profileRow->addWidget(browseProfile);
    auto *outputRow = new QHBoxLayout;
    outputRow->addWidget(m_output, 1);
    outputRow->addWidget(browseOutput);
    auto *form = new QFormLayout;
    ScanForm::addRow(this, form, tr("&Profile:"), m_profile, profileRow);
    form->addRow(tr("&Format:"), m_format);
    form->addRow(tr("E&ndpoint:"), m_endpoint);
    form->addRow(tr("Poll &interval:"), m_interval);
    form->addRow(tr("&Verify from:"), m_verify);
    ScanForm::addRow(this, form, tr("O&utput file:"), m_output, outputRow);

    auto *buttons = new QDialogButtonBox(QDialogButtonBox::Close, this);
    buttons->addButton(m_export, QDialogButtonBox::ActionRole);
    auto *layout = new QVBoxLayout(this);
    layout->addLayout(form);
    layout->addWidget(m_status, 1);
    layout->addWidget(buttons);
    resize(640, 360);
    m_status->setText(tr("Writes the profile's register map for the tool that will poll the device (mbscope export-map)."));

    connect(m_export, &QPushButton::clicked, this, [this] { exportMap(); });
    connect(browseProfile, &QPushButton::clicked, this, &ExportMapDialog::browseProfile);
    connect(browseOutput, &QPushButton::clicked, this, &ExportMapDialog::browseOutput);
    connect(buttons, &QDialogButtonBox::rejected, this, &ExportMapDialog::reject);
}

void ExportMapDialog::setProfile(const QString &profile)
{
    m_profile->setText(profile);
}

void ExportMapDialog::problem(const QString &text)
{
    ScanForm::showProblem(m_status, text);
    Q_EMIT exported(false);
}

bool ExportMapDialog::exportMap()
{
    if (m_running)
        return false;
    if (m_profile->text().trimmed().isEmpty()) {
        problem(tr("Which profile? Give a shipped profile's name or a JSON file."));
        return false;
    }
    const ProfileLoadResult loaded = ProfileLoader::load(m_profile->text().trimmed());
    if (!loaded.ok) {
        problem(loaded.errorText());
        return false;
    }
    const DeviceProfile &profile = loaded.profile;
    const auto format = MapExportFormat(m_format->currentData().toInt());
    MapExportInput input = MapExportInput::fromProfile(profile);
    if (input.points.isEmpty()) {
        problem(tr("%1 has no table entries to export.").arg(profile.source));
        return false;
    }
    if (!input.tooLarge.isEmpty()) {
        problem(tr("Nothing exported: %n value(s) cannot be read whole within the device's limits.maxQuantity: %1", nullptr,
                   int(input.tooLarge.size()))
                    .arg(input.tooLarge.join(QStringLiteral("; "))));
        return false;
    }
    input.intervalMs = m_interval->value();
    if (const QString text = m_endpoint->text().trimmed(); !text.isEmpty()) {
        const LinkUrl::Result parsed = LinkUrl::parse(text);
        if (!parsed.url) {
            problem(tr("Endpoint: %1").arg(parsed.error));
            return false;
        }
        input.endpoint = *parsed.url;
    } else {
        input.endpoint = MapExporter::defaultEndpoint(profile, format);
    }
    if (const QString why = MapExporter::unsupportedEndpoint(format, input.endpoint); !why.isEmpty()) {
        problem(tr("Endpoint %1: %2").arg(input.endpoint.toString(), why));
        return false;
    }
    const QString path = m_output->text().trimmed();
    if (path.isEmpty()) {
        problem(tr("Choose the output file."));
        return false;
    }

    QString verified;
    if (const QString text = m_verify->text().trimmed(); !text.isEmpty()) {
        const LinkUrl::Result parsed = LinkUrl::parse(text);
        if (!parsed.url) {
            problem(tr("Verify from: %1").arg(parsed.error));
            return false;
        }
        m_running = true;
        m_export->setEnabled(false);
        m_status->setText(tr("Reading every value once from %1\u2026").arg(parsed.url->toString()));
        const QList<MapVerdict> verdicts = MapVerifier::judge(
            input.points, input.blocks, readBlocks(m_sampler, input.paced(*parsed.url), input.timeoutMs, input.points, input.blocks));
        m_running = false;
        m_export->setEnabled(true);
        QStringList bad;
        for (const MapVerdict &v : verdicts) {
            if (v.ok())
                continue;
            const MapPoint &p = input.points.at(v.point);
            bad.append(tr("unit %1 %2 %3 (%4): %5").arg(int(p.unitId)).arg(p.tableKey()).arg(p.address).arg(p.label, v.problem));
        }
        if (!bad.isEmpty()) {
            const qsizetype shown = std::min<qsizetype>(bad.size(), 8);
            problem(tr("Refused: %1 of %2 values read from %3 are not usable; nothing written.")
                        .arg(bad.size())
                        .arg(verdicts.size())
                        .arg(parsed.url->toString())
                    + QLatin1Char('\n') + bad.mid(0, shown).join(QLatin1Char('\n'))
                    + (bad.size() > shown ? tr("\nand %n more", nullptr, int(bad.size() - shown)) : QString()));
            return false;
        }
        verified = tr("Verified: %1 values read from %2 are finite and inside their ranges. ").arg(verdicts.size()).arg(parsed.url->toString());
    }

    QSaveFile file(path);
    const QByteArray bytes = MapExporter::write(format, input).toUtf8();
    if (!file.open(QIODevice::WriteOnly) || file.write(bytes) != bytes.size() || !file.commit()) {
        problem(tr("Cannot write %1: %2").arg(QDir::toNativeSeparators(path), file.errorString()));
        return false;
    }
    m_status->setText(verified
                      + tr("Wrote %1 values in %2 blocks to %3 (%4).")
                            .arg(input.points.size())
                            .arg(input.blocks.size())
                            .arg(QDir::toNativeSeparators(path), MapExporter::formatName(format)));
    Q_EMIT exported(true);
    return true;
}

void ExportMapDialog::reject()
{
    m_sampler->stop();
    QDialog::reject();
}

void ExportMapDialog::browseProfile()
{
    const QString path = QFileDialog::getOpenFileName(this, tr("Device profile"), LastFolder::start(QString()),
                                                      tr("Device profiles (*.json)"));
    LastFolder::remember(path);
    if (!path.isEmpty())
        m_profile->setText(path);
}

void ExportMapDialog::browseOutput()
{
    const auto format = MapExportFormat(m_format->currentData().toInt());
    const QString suggested = format == MapExportFormat::NodeRed ? QStringLiteral("flow.json")
                              : format == MapExportFormat::Csv   ? QStringLiteral("map.csv")
                              : format == MapExportFormat::Telegraf ? QStringLiteral("telegraf.conf")
                                                                    : QStringLiteral("map.yaml");
    const QString path = QFileDialog::getSaveFileName(this, tr("Export to"), LastFolder::start(suggested));
    LastFolder::remember(path);
    if (!path.isEmpty())
        m_output->setText(path);
}

} // namespace mbscope
