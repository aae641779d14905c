#include "export_size_dialog.h"

#include <QDialog>
#include <QDialogButtonBox>
#include <QFormLayout>
#include <QSpinBox>

namespace pat::ui {

QSize ask_export_size(QWidget* parent, QSize current) {
  QDialog dialog(parent);
  dialog.setWindowTitle(QDialog::tr("Export size"));
  auto* form = new QFormLayout(&dialog);
  auto* width = new QSpinBox(&dialog);
  auto* height = new QSpinBox(&dialog);
  for (QSpinBox* box : {width, height}) {
    box->setRange(50, 20000);
    box->setSuffix(QDialog::tr(" px"));
  }
  width->setValue(current.width());
  height->setValue(current.height());
  form->addRow(QDialog::tr("Width (PNG pixels, PDF/SVG points):"), width);
  form->addRow(QDialog::tr("Height (all plots together):"), height);
  auto* buttons = new QDialogButtonBox(QDialogButtonBox::Ok | QDialogButtonBox::Cancel, &dialog);
  form->addRow(buttons);
  QObject::connect(buttons, &QDialogButtonBox::accepted, &dialog, &QDialog::accept);
  QObject::connect(buttons, &QDialogButtonBox::rejected, &dialog, &QDialog::reject);
  if (dialog.exec() != QDialog::Accepted) return current;
  return {width->value(), height->value()};
}

}  // namespace pat::ui
