using System.Windows;
using System.Windows.Controls;
using System.Windows.Media;
using OperatorPanel.ViewModels.Alarms;

namespace OperatorPanel.App.Views;

/// <summary>
/// The Alarms window; all behaviour is in AlarmsViewModel. The code here is geometry only: it tells the view model which
/// rows the grid shows whole (so it can count the pending alarms out of view) and scrolls the first of those into view.
/// </summary>
public partial class AlarmsView : UserControl
{
    public AlarmsView()
    {
        InitializeComponent();
        DataContextChanged += (_, _) => Dispatcher.BeginInvoke(ReportVisibleRows, System.Windows.Threading.DispatcherPriority.Loaded);
    }

    private void OnAlarmGridScrollChanged(object sender, ScrollChangedEventArgs e) => ReportVisibleRows();

    /// <summary>The History tab hides the alarm table: none of its rows is in view then, and all again when it returns.</summary>
    private void OnAlarmGridVisibleChanged(object sender, DependencyPropertyChangedEventArgs e) =>
        Dispatcher.BeginInvoke(ReportVisibleRows, System.Windows.Threading.DispatcherPriority.Loaded);

    private void OnShowHiddenPending(object sender, RoutedEventArgs e)
    {
        if (DataContext is AlarmsViewModel { FirstHiddenPending: { } row })
        {
            AlarmTabs.SelectedIndex = 0;
            AlarmGrid.ScrollIntoView(row);
        }
    }

    /// <summary>Rows are realized only near the viewport (virtualization); a row counts when it lies whole inside it.</summary>
    private void ReportVisibleRows()
    {
        if (DataContext is not AlarmsViewModel alarms)
        {
            return;
        }

        var (first, count) = (-1, 0);
        ScrollContentPresenter? viewport = null;
        for (var i = 0; i < AlarmGrid.Items.Count; i++)
        {
            if (AlarmGrid.ItemContainerGenerator.ContainerFromIndex(i) is not DataGridRow { IsVisible: true } row)
            {
                continue;
            }

            viewport ??= Ancestor<ScrollContentPresenter>(row);
            if (viewport is null)
            {
                continue;
            }

            var bounds = row.TransformToAncestor(viewport).TransformBounds(new Rect(row.RenderSize));
            if (bounds.Top >= -0.5 && bounds.Bottom <= viewport.ActualHeight + 0.5)
            {
                first = first < 0 ? i : first;
                count++;
            }
        }

        alarms.ShowVisibleRows(Math.Max(first, 0), count);
    }

    private static T? Ancestor<T>(DependencyObject element)
        where T : DependencyObject
    {
        for (var parent = VisualTreeHelper.GetParent(element); parent is not null; parent = VisualTreeHelper.GetParent(parent))
        {
            if (parent is T found)
            {
                return found;
            }
        }

        return null;
    }
}
