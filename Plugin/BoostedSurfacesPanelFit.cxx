#include "BoostedSurfacesPanelFit.h"

#include "pqActiveObjects.h"
#include "pqApplicationCore.h"
#include "pqCoreUtilities.h"
#include "pqPipelineSource.h"
#include "pqProxyWidget.h"
#include "pqSMProxy.h"
#include "pqServerManagerModel.h"
#include "vtkPVDataInformation.h"
#include "vtkPVXMLElement.h"
#include "vtkSMSourceProxy.h"

#include <QHeaderView>
#include <QMetaObject>
#include <QPointer>
#include <QTableView>
#include <QTimer>
#include <QVariant>
#include <QWidget>


namespace
{
bool HasHint(vtkSMProxy* proxy, const char* name)
{
  vtkPVXMLElement* hints = proxy ? proxy->GetHints() : nullptr;
  return hints && hints->FindNestedElementByName(name);
}

// The columns share the table's width instead of each taking its contents' width (ParaView's
// ResizeToContents: the dipole field's 9 columns need 539 pixels), down to the header's minimum
// section size (28 pixels here); longer labels and values are cut.
void FitColumns(QTableView* table)
{
  QHeaderView* header = table->horizontalHeader();
  header->setStretchLastSection(false); // else the last column keeps its contents' width
  header->setSectionResizeMode(QHeaderView::Stretch);
}

bool HasOutput(vtkSMProxy* proxy)
{
  auto* source = vtkSMSourceProxy::SafeDownCast(proxy);
  if (!source || source->GetNumberOfOutputPorts() == 0)
  {
    return false;
  }
  const double* bounds = source->GetDataInformation(0)->GetBounds();
  return bounds[0] <= bounds[1];
}
}

BoostedSurfacesPanelFit::BoostedSurfacesPanelFit(QObject* parent)
  : QObject(parent)
{
}

void BoostedSurfacesPanelFit::startup()
{
  pqServerManagerModel* model = pqApplicationCore::instance()->getServerManagerModel();
  QObject::connect(model, &pqServerManagerModel::sourceAdded, this,
    &BoostedSurfacesPanelFit::watchSource);
  for (pqPipelineSource* source : model->findItems<pqPipelineSource*>())
  {
    this->watchSource(source);
  }
  QObject::connect(&pqActiveObjects::instance(), &pqActiveObjects::sourceChanged, this,
    &BoostedSurfacesPanelFit::fitLater);
}

void BoostedSurfacesPanelFit::watchSource(pqPipelineSource* source)
{
  vtkSMProxy* proxy = source ? source->getProxy() : nullptr;
  if (HasHint(proxy, "WidgetsSizedToOutput") || HasHint(proxy, "TableColumnsFitPanel"))
  {
    QObject::connect(source,
      static_cast<void (pqPipelineSource::*)(pqPipelineSource*)>(&pqPipelineSource::dataUpdated),
      this, &BoostedSurfacesPanelFit::fitLater);
  }
}

void BoostedSurfacesPanelFit::fitLater(pqPipelineSource* source)
{
  QPointer<pqPipelineSource> guarded(source);
  QTimer::singleShot(0, this, [this, guarded]() {
    if (guarded)
    {
      this->fit(guarded);
    }
  });
}

void BoostedSurfacesPanelFit::fit(pqPipelineSource* source)
{
  vtkSMProxy* proxy = source->getProxy();
  const bool sizeWidgets = HasHint(proxy, "WidgetsSizedToOutput");
  const bool fitTables = HasHint(proxy, "TableColumnsFitPanel");
  if (!sizeWidgets && !fitTables)
  {
    return;
  }
  QWidget* mainWidget = pqCoreUtilities::mainWidget();
  if (!mainWidget)
  {
    return;
  }
  for (pqProxyWidget* panel : mainWidget->findChildren<pqProxyWidget*>())
  {
    if (panel->proxy() != proxy)
    {
      continue;
    }
    if (sizeWidgets)
    {
      // By class name and Qt's meta-object system only: pqInteractivePropertyWidgetAbstract is in
      // pqApplicationComponents, which pvpython and pvserver (they load this plugin too) lack.
      for (QWidget* widget : panel->findChildren<QWidget*>())
      {
        if (!widget->inherits("pqInteractivePropertyWidgetAbstract") ||
          widget->property("dataSource").value<pqSMProxy>())
        {
          continue; // not an interactive widget, or placed by ParaView from its group's Input
        }
        QMetaObject::invokeMethod(widget, "setDataSource", Q_ARG(vtkSMProxy*, proxy));
        // Placed once, when the first output exists; afterwards ParaView places it whenever
        // the panel is selected.
        if (HasOutput(proxy) && !widget->property("boostedSurfacesPlaced").toBool())
        {
          widget->setProperty("boostedSurfacesPlaced", true);
          QMetaObject::invokeMethod(widget, "placeWidget");
        }
      }
    }
    if (fitTables)
    {
      for (QTableView* table : panel->findChildren<QTableView*>())
      {
        FitColumns(table);
      }
    }
  }
}
