using System.Windows;
using System.Windows.Controls;
using System.Windows.Threading;

namespace OperatorPanel.App.Views;

/// <summary>The Memory window: M and V cells, edited in place; all behaviour is in MemoryViewModel.</summary>
public partial class MemoryView : UserControl
{
    public MemoryView() => InitializeComponent();

    /// <summary>
    /// Edit (or a double-click) puts the cursor in the value's editor with the old value selected, so the operator types
    /// the new value at once and Enter writes it. Focus is a view matter; the edit itself is MemoryCellViewModel's.
    /// </summary>
    private void EditorVisibleChanged(object sender, DependencyPropertyChangedEventArgs e)
    {
        if (sender is TextBox { IsVisible: true } editor)
        {
            editor.Dispatcher.BeginInvoke(DispatcherPriority.Input, () =>
            {
                editor.Focus();
                editor.SelectAll();
            });
        }
    }
}
