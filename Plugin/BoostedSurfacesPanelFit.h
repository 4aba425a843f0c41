// The GUI side of the plugin (paraview_plugin_add_auto_start; only in the Qt client): fits the
// Properties panel of the plugin's proxies to their data and to the panel.
//
// * Widgets sized to the data (hint <WidgetsSizedToOutput/>): ParaView 5.11 places an interactive
//   widget by the data of its property group's Input, and a source has none, so its plane widgets
//   stay a unit box. For such a proxy, every interactive widget whose group has no Input takes the
//   proxy itself as its data source (pqInteractivePropertyWidgetAbstract::setDataSource) and is
//   placed once its output exists; ParaView places it again whenever the panel is selected, as it
//   does a filter's. ParaView's handles have no size of their own in the world (their
//   placeWidget() does nothing): HandleSizedToData sizes them to the source's output.
// * Table columns that fit the panel (hint <TableColumnsFitPanel/>): the tables of repeated
//   properties (the generator rows and the other lists) get columns that share the table's width
//   (QHeaderView::Stretch) instead of ParaView's widths by contents, so all columns show in a
//   table at least (columns x the header's minimum section size) wide.
#ifndef BoostedSurfaces_BoostedSurfacesPanelFit_h
#define BoostedSurfaces_BoostedSurfacesPanelFit_h

#include <QObject>

class pqPipelineSource;

class BoostedSurfacesPanelFit : public QObject
{
  Q_OBJECT

public:
  explicit BoostedSurfacesPanelFit(QObject* parent = nullptr);
  ~BoostedSurfacesPanelFit() override = default;

  void startup();
  void shutdown() {}

private Q_SLOTS:
  void watchSource(pqPipelineSource* source);
  // Deferred to the event loop: the Properties panel builds its widgets after these signals.
  void fitLater(pqPipelineSource* source);

private:
  void fit(pqPipelineSource* source);
};

#endif
