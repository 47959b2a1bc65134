#pragma once

#include <QtSerialBus/QModbusServer>

namespace mbscope {

class SimUnit;

// Qt SerialBus's server data model and request semantics, backed by a SimUnit instead of
// QModbusServer's single block per table: readData/writeData (the hooks QModbusServer offers for
// another backing store) read and write the unit's ranges, so an address outside every range is
// "out of the map" and gets exception 02 from QModbusServer itself. It never opens a device:
// open/close do nothing, and requests reach it only through handle(), which is
// QModbusServer::processRequest. SimProcessor decides which function codes go here.
class SimModbusServer final : public QModbusServer
{
    Q_OBJECT
public:
    explicit SimModbusServer(SimUnit *unit, QObject *parent = nullptr);

    // QModbusServer::processRequest for one request PDU.
    [[nodiscard]] QModbusResponse handle(const QModbusPdu &request) { return processRequest(request); }

    // Replaces the unit's ranges of each table in map by one writable range per data unit.
    bool setMap(const QModbusDataUnitMap &map) override;

protected:
    bool open() override;
    void close() override;
    bool readData(QModbusDataUnit *newData) const override;
    bool writeData(const QModbusDataUnit &unit) override;

private:
    SimUnit *m_unit;
};

} // namespace mbscope
