using System.Windows.Controls;

namespace OperatorPanel.App.Views;

/// <summary>The Memory window: M and V cells, edited in place; all behaviour is in MemoryViewModel.</summary>
public partial class MemoryView : UserControl
{
    public MemoryView() => InitializeComponent();
}
