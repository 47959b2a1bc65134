#include "registertable.h"

#include "common/editablecellsview.h"

#include "common/coretext.h"
#include "registertablemodel.h"

#include <QtCore/QSettings>
#include <QtWidgets/QComboBox>
#include <QtWidgets/QHeaderView>
#include <QtWidgets/QLabel>
#include <QtWidgets/QMenu>
#include <QtWidgets/QTableView>
#include <QtWidgets/QToolBar>
#include <QtWidgets/QVBoxLayout>

namespace mbscope {

namespace {

constexpr RegisterType kTypes[] = {
    RegisterType::UInt16, RegisterType::Int16,  RegisterType::Hex16,  RegisterType::Binary16,
    RegisterType::Ascii,  RegisterType::UInt32, RegisterType::Int32,  RegisterType::UInt64,
    RegisterType::Int64,  RegisterType::Float32, RegisterType::Float64,
};

// The orders a type tells apart: AB and BA for one register, four for wider values.
QList<RegisterOrder> ordersOf(RegisterType type)
{
    if (RegisterFormat::registerCount(type) == 1)
        return {RegisterOrder::ABCD, RegisterOrder::BADC};
    return {RegisterOrder::ABCD, RegisterOrder::CDAB, RegisterOrder::BADC, RegisterOrder::DCBA};
}

QString orderLabel(RegisterType type, RegisterOrder order)
{
    const RegisterFormat f(type, order);
    const int width = f.registerCount();
    if (width == 1)
        return order == RegisterOrder::ABCD ? QCoreApplication::translate("mbscope::RegisterTable", "AB (high byte first)") : QCoreApplication::translate("mbscope::RegisterTable", "BA (byte swap)");
    switch (order) {
    case RegisterOrder::ABCD: return QCoreApplication::translate("mbscope::RegisterTable", "%1 (big endian)").arg(f.orderName());
    case RegisterOrder::CDAB: return QCoreApplication::translate("mbscope::RegisterTable", "%1 (word swap)").arg(f.orderName());
    case RegisterOrder::BADC: return QCoreApplication::translate("mbscope::RegisterTable", "%1 (byte swap)").arg(f.orderName());
    case RegisterOrder::DCBA: return QCoreApplication::translate("mbscope::RegisterTable", "%1 (little endian)").arg(f.orderName());
    }
    return f.orderName();
}

} // namespace

RegisterTable::RegisterTable(QWidget *parent)
    : QWidget(parent),
      m_model(new RegisterTableModel(this)),
      m_view(new EditableCellsView(this)),
      m_toolBar(new QToolBar(this)),
      m_message(new QLabel(this))
{
    setObjectName(QStringLiteral("registerTable"));
    m_view->setObjectName(QStringLiteral("registerTableView"));
    m_view->setModel(m_model);
    m_view->verticalHeader()->hide();
    m_view->verticalHeader()->setDefaultSectionSize(m_view->fontMetrics().height() + 6);
    // Numbers stay beside their names: no column stretches to the view's edge.
    m_view->horizontalHeader()->setStretchLastSection(false);
    m_view->horizontalHeader()->setContextMenuPolicy(Qt::CustomContextMenu);
    m_view->setSelectionBehavior(QAbstractItemView::SelectItems);
    m_view->setEditTriggers(QAbstractItemView::DoubleClicked | QAbstractItemView::EditKeyPressed
                            | QAbstractItemView::AnyKeyPressed);
    m_view->setAlternatingRowColors(true);

    m_message->setObjectName(QStringLiteral("registerTableMessage"));
    m_message->setWordWrap(true);
    m_message->setTextInteractionFlags(Qt::TextSelectableByMouse);
    m_message->hide();

    buildToolBar();

    auto *layout = new QVBoxLayout(this);
    layout->setContentsMargins(0, 0, 0, 0);
    layout->setSpacing(2);
    layout->addWidget(m_toolBar);
    layout->addWidget(m_message);
    layout->addWidget(m_view);

    connect(m_model, &RegisterTableModel::writeRequested, this, [this](const QByteArray &pdu, const QString &what) {
        m_showingProblem = false;
        m_message->setText(tr("Write requested: %1").arg(what));
        m_message->setStyleSheet(QString());
        m_message->show();
        Q_EMIT writeRequested(pdu, what);
    });
    connect(m_model, &RegisterTableModel::editRefused, this, &RegisterTable::showMessage);
    connect(m_model, &RegisterTableModel::answerRefused, this, &RegisterTable::showMessage);
    connect(m_model, &RegisterTableModel::layoutOfValuesChanged, this, [this] {
        if (m_currentValue >= m_model->valueColumnCount())
            m_currentValue = 0;
        applySpans();
        m_view->resizeColumnsToContents();
        refreshToolBar();
    });
    connect(m_view->horizontalHeader(), &QHeaderView::customContextMenuRequested, this,
            &RegisterTable::showHeaderMenu);
    connect(m_view->horizontalHeader(), &QHeaderView::sectionClicked, this, [this](int section) {
        if (const int vi = m_model->valueIndexOf(section); vi >= 0)
            setCurrentValueIndex(vi);
    });
    connect(m_view, &QTableView::clicked, this, [this](const QModelIndex &index) {
        if (const int vi = m_model->valueIndexOf(index.column()); vi >= 0)
            setCurrentValueIndex(vi);
    });
    refreshToolBar();
}

void RegisterTable::buildToolBar()
{
    m_toolBar->setObjectName(QStringLiteral("registerTableToolBar"));
    m_toolBar->setIconSize(QSize(16, 16));

    m_columnLabel = new QLabel(m_toolBar);
    m_toolBar->addWidget(m_columnLabel);
    m_typeBox = new QComboBox(m_toolBar);
    m_typeBox->setObjectName(QStringLiteral("registerTableFormat"));
    m_typeBox->setToolTip(tr("What the registers of the current value column stand for"));
    for (RegisterType type : kTypes)
        m_typeBox->addItem(RegisterFormat(type).typeName(), int(type));
    m_toolBar->addWidget(m_typeBox);

    m_toolBar->addWidget(new QLabel(tr(" Order "), m_toolBar));
    m_orderBox = new QComboBox(m_toolBar);
    m_orderBox->setObjectName(QStringLiteral("registerTableOrder"));
    m_orderBox->setToolTip(tr("Word and byte order of the current value column: the order the value's "
                              "bytes travel in, most significant named A"));
    m_toolBar->addWidget(m_orderBox);

    m_addColumn = m_toolBar->addAction(tr("+ Column"));
    m_addColumn->setToolTip(tr("Add a value column showing the same registers in another format"));
    m_removeColumn = m_toolBar->addAction(QStringLiteral("\u2212 ") + tr("Column"));
    m_removeColumn->setToolTip(tr("Remove the current value column"));
    m_toolBar->addSeparator();

    m_toolBar->addWidget(new QLabel(tr("Write with "), m_toolBar));
    m_writeBox = new QComboBox(m_toolBar);
    m_writeBox->setObjectName(QStringLiteral("registerTableWriteFunction"));
    m_writeBox->setToolTip(tr("The function an edited value is written with"));
    m_toolBar->addWidget(m_writeBox);
    m_toolBar->addSeparator();

    m_profileLabel = new QLabel(m_toolBar);
    m_profileLabel->setObjectName(QStringLiteral("registerTableProfile"));
    m_toolBar->addWidget(m_profileLabel);

    connect(m_typeBox, &QComboBox::currentIndexChanged, this, [this] {
        if (m_refreshing)
            return;
        applyTypeAndOrder();
    });
    connect(m_orderBox, &QComboBox::currentIndexChanged, this, [this] {
        if (m_refreshing)
            return;
        applyTypeAndOrder();
    });
    connect(m_writeBox, &QComboBox::currentIndexChanged, this, [this] {
        if (m_refreshing || m_writeBox->currentIndex() < 0)
            return;
        m_model->setWriteChoice(WriteChoice(m_writeBox->currentData().toInt()));
    });
    connect(m_addColumn, &QAction::triggered, this, [this] {
        m_model->addValueColumn(m_model->valueFormats().value(m_currentValue));
        setCurrentValueIndex(int(m_model->valueFormats().size()) - 1);
    });
    connect(m_removeColumn, &QAction::triggered, this, [this] { m_model->removeValueColumn(m_currentValue); });
}

void RegisterTable::applyTypeAndOrder()
{
    const auto type = RegisterType(m_typeBox->currentData().toInt());
    const RegisterOrder order = m_orderBox->currentIndex() >= 0 ? RegisterOrder(m_orderBox->currentData().toInt())
                                                                : RegisterOrder::ABCD;
    m_model->setValueFormat(m_currentValue, RegisterFormat(type, order));
    refreshToolBar();
}

void RegisterTable::setCurrentValueIndex(int valueIndex)
{
    if (valueIndex < 0 || valueIndex >= m_model->valueFormats().size())
        return;
    m_currentValue = valueIndex;
    refreshToolBar();
}

void RegisterTable::refreshToolBar()
{
    m_refreshing = true;
    const bool bits = m_model->hasAnswer() && m_model->answer().isBits();
    const RegisterFormat format = m_model->valueFormats().value(m_currentValue);
    m_columnLabel->setText(tr("Column %1 ").arg(m_currentValue + 1));
    m_typeBox->setCurrentIndex(m_typeBox->findData(int(format.type())));
    m_orderBox->clear();
    for (RegisterOrder order : ordersOf(format.type()))
        m_orderBox->addItem(orderLabel(format.type(), order), int(order));
    m_orderBox->setCurrentIndex(m_orderBox->findData(int(format.order())));
    for (QWidget *w : {static_cast<QWidget *>(m_typeBox), static_cast<QWidget *>(m_orderBox)})
        w->setEnabled(!bits);
    m_addColumn->setEnabled(!bits);
    m_removeColumn->setEnabled(!bits && m_model->valueFormats().size() > 1);
    m_profileLabel->setText(m_model->hasProfile() ? tr("Profile: %1").arg(m_model->profileName())
                                                  : tr("Profile: none"));
    m_profileLabel->setToolTip(m_model->hasProfile()
                                   ? tr("Names, scaling and units come from the device profile %1")
                                         .arg(m_model->profileName())
                                   : tr("No device profile: no names or scaling"));
    refreshWriteChoices();
    m_refreshing = false;
}

void RegisterTable::refreshWriteChoices()
{
    m_writeBox->clear();
    const ModbusTable table = m_model->answer().table;
    if (!ModiconReference::isWritable(table)) {
        m_writeBox->addItem(tr("read-only (%1)").arg(fieldText(ModiconReference::tableName(table))), -1);
        m_writeBox->setEnabled(false);
        return;
    }
    m_writeBox->setEnabled(true);
    const WriteChoice choice = m_model->writeChoice();
    if (table == ModbusTable::Coils) {
        // Automatic and Single both write a coil with 05; the model keeps the choice as made, so
        // going back to registers shows it again.
        m_writeBox->addItem(tr("05 Write Single Coil"), int(WriteChoice::Single));
        m_writeBox->addItem(tr("0F Write Multiple Coils"), int(WriteChoice::Multiple));
        m_writeBox->setCurrentIndex(choice == WriteChoice::Multiple ? 1 : 0);
        return;
    }
    m_writeBox->addItem(tr("06 or 10 by width"), int(WriteChoice::Automatic));
    m_writeBox->addItem(tr("06 Write Single Register"), int(WriteChoice::Single));
    m_writeBox->addItem(tr("10 Write Multiple Registers"), int(WriteChoice::Multiple));
    m_writeBox->setCurrentIndex(qMax(0, m_writeBox->findData(int(choice))));
}

void RegisterTable::applySpans()
{
    m_view->clearSpans();
    const int rows = m_model->rowCount();
    for (int vi = 0; vi < m_model->valueColumnCount(); ++vi) {
        const int column = RegisterTableModel::FirstValueColumn + vi;
        if (m_model->formatOfColumn(column).registerCount() == 1)
            continue;
        for (int row = 0; row < rows; ++row) {
            const int span = m_model->index(row, column).data(RegisterTableModel::SpanRole).toInt();
            if (span > 1)
                m_view->setSpan(row, column, span, 1);
        }
    }
}

void RegisterTable::showMessage(const QString &text)
{
    m_showingProblem = !text.isEmpty();
    m_message->setText(text);
    m_message->setStyleSheet(QStringLiteral("QLabel { color: #a40000; }"));
    m_message->setVisible(m_showingProblem);
}

QString RegisterTable::message() const
{
    return m_message->text();
}

void RegisterTable::showHeaderMenu(const QPoint &position)
{
    const int section = m_view->horizontalHeader()->logicalIndexAt(position);
    const int vi = m_model->valueIndexOf(section);
    if (vi < 0 || (m_model->hasAnswer() && m_model->answer().isBits()))
        return;
    setCurrentValueIndex(vi);
    const RegisterFormat current = m_model->valueFormats().at(vi);
    QMenu menu(this);
    menu.addSection(tr("Column %1 format").arg(vi + 1));
    for (RegisterType type : kTypes) {
        QAction *a = menu.addAction(RegisterFormat(type, current.order()).name());
        a->setCheckable(true);
        a->setChecked(type == current.type());
        connect(a, &QAction::triggered, this, [this, vi, type, current] {
            m_model->setValueFormat(vi, RegisterFormat(type, current.order()));
            refreshToolBar();
        });
    }
    menu.addSection(tr("Order"));
    for (RegisterOrder order : ordersOf(current.type())) {
        QAction *a = menu.addAction(orderLabel(current.type(), order));
        a->setCheckable(true);
        a->setChecked(order == current.order());
        connect(a, &QAction::triggered, this, [this, vi, current, order] {
            m_model->setValueFormat(vi, RegisterFormat(current.type(), order));
            refreshToolBar();
        });
    }
    QAction *all = menu.addAction(tr("Use this order in every column"));
    connect(all, &QAction::triggered, this, [this, current] {
        m_model->setOrder(current.order());
        refreshToolBar();
    });
    menu.addSeparator();
    menu.addAction(m_addColumn);
    menu.addAction(m_removeColumn);
    menu.exec(m_view->horizontalHeader()->mapToGlobal(position));
}

bool RegisterTable::showTransaction(const Transaction &transaction, Framing framing)
{
    const bool ok = m_model->updateFromTransaction(transaction, framing);
    if (ok && m_showingProblem)
        showMessage(QString());
    return ok;
}

bool RegisterTable::showAnswer(const QByteArray &requestPdu, const QByteArray &responsePdu)
{
    const bool ok = m_model->update(requestPdu, responsePdu);
    if (ok && m_showingProblem)
        showMessage(QString());
    return ok;
}

void RegisterTable::setProfile(const UnitProfile &unit, const QString &profileName)
{
    m_model->setProfile(unit, profileName);
}

void RegisterTable::clearProfile()
{
    m_model->clearProfile();
}

void RegisterTable::storeFormats() const
{
    QStringList formats;
    for (const RegisterFormat &format : m_model->valueFormats())
        formats << format.name();
    QSettings().setValue(QStringLiteral("registers/formats"), formats);
}

void RegisterTable::restoreFormats()
{
    QList<RegisterFormat> formats;
    for (const QString &name : QSettings().value(QStringLiteral("registers/formats")).toStringList()) {
        const RegisterFormatResult format = RegisterFormat::parse(name);
        if (format.ok)
            formats.append(format.format);
    }
    if (!formats.isEmpty())
        m_model->setValueFormats(formats);
}

} // namespace mbscope
