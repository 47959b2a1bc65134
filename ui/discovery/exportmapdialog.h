#pragma once

#include <QtWidgets/QDialog>

class QComboBox;
class QLabel;
class QLineEdit;
class QPushButton;
class QSpinBox;

namespace mbscope {

class BlockSampler;

// Tools > Export map: what `mbscope export-map` does, from the window: a device profile's register
// map written for the tool that will poll the device (Node-RED, Telegraf, Home Assistant,
// modbus_exporter, CSV; core/mapexport), optionally after reading every value once from a target
// through the map (Verify) and refusing the export when one is not finite or outside its declared
// range, naming the row. Reads only.
class ExportMapDialog : public QDialog
{
    Q_OBJECT
public:
    explicit ExportMapDialog(QWidget *parent = nullptr);

    void setProfile(const QString &profile);
    // Writes the export to the output file; false, with the reason shown, when it refused or could not.
    bool exportMap();
    [[nodiscard]] bool isRunning() const { return m_running; }

Q_SIGNALS:
    void exported(bool written);

protected:
    void reject() override;

private:
    void problem(const QString &text);
    void browseProfile();
    void browseOutput();

    QLineEdit *m_profile;
    QComboBox *m_format;
    QLineEdit *m_endpoint;
    QSpinBox *m_interval;
    QLineEdit *m_verify;
    QLineEdit *m_output;
    QPushButton *m_export;
    QLabel *m_status;
    BlockSampler *m_sampler;
    bool m_running = false;
};

} // namespace mbscope
