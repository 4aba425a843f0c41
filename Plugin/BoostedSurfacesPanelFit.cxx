#include "BoostedSurfacesPanelFit.h"

#include "HandleSizedToData.h"
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
#include <QStyle>
#include <QTableView>
#include <QTimer>
#include <QVariant>
#include <QWidget>

#include <algorithm>
#include <cmath>


namespace
{
bool HasHint(vtkSMProxy* proxy, const char* name)
{
  vtkPVXMLElement* hints = proxy ? proxy->GetHints() : nullptr;
  return hints && hints->FindNestedElementByName(name);
}

// The columns share the table's width instead of each taking its contents' width (ParaView's
// ResizeToContents: the dipole field's 9 columns need 539 pixels), down to one digit's width and
// the header's margins (the style's minimum section, 15 pixels here, would keep the nine columns
// wider than the 132 pixels of the default panel's table); longer labels and values are cut.
void FitColumns(QTableView* table)
{
  QHeaderView* header = table->horizontalHeader();
  header->setStretchLastSection(false); // else the last column keeps its contents' width
  const int margin = header->style()->pixelMetric(QStyle::PM_HeaderMargin, nullptr, header);
  const int digit = header->fontMetrics().horizontalAdvance(QLatin1Char('0'));
  header->setMinimumSectionSize(std::min(header->minimumSectionSize(), digit + 2 * margin));
  header->setSectionResizeMode(QHeaderView::Stretch);
}

// The diagonal of the first output's bounds; 0 before the first update (no bounds yet).
double OutputDiagonal(vtkSMProxy* proxy)
{
  auto* source = vtkSMSourceProxy::SafeDownCast(proxy);
  if (!source || source->GetNumberOfOutputPorts() == 0)
  {
    return 0.0;
  }
  const double* bounds = source->GetDataInformation(0)->GetBounds();
  if (!(bounds[0] <= bounds[1]))
  {
    return 0.0;
  }
  const double diagonal = std::sqrt((bounds[1] - bounds[0]) * (bounds[1] - bounds[0]) +
    (bounds[3] - bounds[2]) * (bounds[3] - bounds[2]) +
    (bounds[5] - bounds[4]) * (bounds[5] - bounds[4]));
  // A single point has bounds but no size: sized as data of diagonal 1.
  return diagonal > 0.0 ? diagonal : 1.0;
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
      const double diagonal = OutputDiagonal(proxy);
      for (QWidget* widget : panel->findChildren<QWidget*>())
      {
        if (!widget->inherits("pqInteractivePropertyWidgetAbstract"))
        {
          continue;
        }
        const vtkSMProxy* dataSource = widget->property("dataSource").value<pqSMProxy>();
        if (!dataSource || dataSource == proxy)
        {
          // Not placed by ParaView from its group's Input: placed by this source's output.
          QMetaObject::invokeMethod(widget, "setDataSource", Q_ARG(vtkSMProxy*, proxy));
          // Placed once, when the first output exists; afterwards ParaView places it whenever
          // the panel is selected.
          if (diagonal > 0.0 && !widget->property("boostedSurfacesPlaced").toBool())
          {
            widget->setProperty("boostedSurfacesPlaced", true);
            QMetaObject::invokeMethod(widget, "placeWidget");
          }
          HandleSizedToData::Attach(widget, diagonal); // handles only
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
