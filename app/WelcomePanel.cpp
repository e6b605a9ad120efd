#include "app/WelcomePanel.h"

#include "app/ApplicationIcon.h"

#include <QEvent>
#include <QHBoxLayout>
#include <QLabel>
#include <QStringList>
#include <QVBoxLayout>

namespace prisca::app {

namespace {

constexpr int kTextWidth = 640;  // px; long lines are hard to read on a wide lab monitor
constexpr int kLogoSize = 96;    // px

QLabel* makeTextLabel(QWidget* parent, const QString& objectName) {
    auto* label = new QLabel(parent);
    label->setObjectName(objectName);
    label->setWordWrap(true);
    label->setTextInteractionFlags(Qt::TextSelectableByMouse);
    return label;
}

}  // namespace

WelcomePanel::WelcomePanel(QWidget* parent)
    : QWidget(parent),
      heading_(makeTextLabel(this, QStringLiteral("welcomeHeading"))),
      summary_(makeTextLabel(this, QStringLiteral("welcomeSummary"))),
      upcoming_(makeTextLabel(this, QStringLiteral("welcomeUpcoming"))),
      notice_(makeTextLabel(this, QStringLiteral("welcomeNotice"))) {
    setObjectName(QStringLiteral("welcomePanel"));

    auto* logo = new QLabel(this);
    logo->setPixmap(applicationIcon().pixmap(kLogoSize, kLogoSize));
    logo->setAlignment(Qt::AlignHCenter);

    QFont headingFont = heading_->font();
    headingFont.setPointSizeF(headingFont.pointSizeF() * 1.5);
    headingFont.setBold(true);
    heading_->setFont(headingFont);
    heading_->setAlignment(Qt::AlignHCenter);
    upcoming_->setTextFormat(Qt::RichText);

    // A column of fixed maximum width, centred both ways. The labels fill the column rather
    // than being aligned in it, so word wrapping gets the full width and the right height.
    auto* column = new QWidget(this);
    column->setMaximumWidth(kTextWidth);
    auto* columnLayout = new QVBoxLayout(column);
    columnLayout->setContentsMargins(0, 0, 0, 0);
    columnLayout->addWidget(logo);
    columnLayout->addSpacing(12);
    columnLayout->addWidget(heading_);
    columnLayout->addSpacing(8);
    columnLayout->addWidget(summary_);
    columnLayout->addWidget(upcoming_);
    columnLayout->addWidget(notice_);

    auto* row = new QHBoxLayout;
    row->addStretch(1);
    row->addWidget(column, 4);
    row->addStretch(1);

    auto* layout = new QVBoxLayout(this);
    layout->addStretch(1);
    layout->addLayout(row);
    layout->addStretch(2);

    retranslateUi();
}

void WelcomePanel::changeEvent(QEvent* event) {
    if (event->type() == QEvent::LanguageChange) {
        retranslateUi();
    }
    QWidget::changeEvent(event);
}

void WelcomePanel::retranslateUi() {
    heading_->setText(tr("Teach a robot to repeat one demonstrated manoeuvre"));
    summary_->setText(
        tr("Drive the robot through the manoeuvre once, on the lab floor or in simulation, while "
           "the ceiling camera or the simulator records what it does. PRISCA then learns from "
           "this single demonstration: it adjusts its controller online, trial after trial, until "
           "the robot repeats the manoeuvre precisely, even when the floor, the tyres or the "
           "starting position differ."));

    // Each item is translated on its own so translators never see the list markup.
    const QStringList items = {
        tr("Simulator: slide-car, acrobot and planar aircraft"),
        tr("Recording: drive by keyboard or gamepad and record a demonstration"),
        tr("Learning: fit the action mapping, run PRISCA or a baseline, and watch the tracking "
           "error live, with an emergency stop"),
        tr("Evaluation: batches of trials, Table I metrics and learning curves"),
    };
    QString html =
        QStringLiteral("<p>%1</p><ul>").arg(tr("Arriving in coming versions:").toHtmlEscaped());
    for (const QString& item : items) {
        html += QStringLiteral("<li>%1</li>").arg(item.toHtmlEscaped());
    }
    html += QStringLiteral("</ul>");
    upcoming_->setText(html);

    notice_->setText(
        tr("This version has no working panels yet: nothing here records, learns or drives a "
           "robot."));
}

}  // namespace prisca::app
