using System.Windows;

namespace OperatorPanel.App;

/// <summary>The shell window; it only hosts views.</summary>
public partial class MainWindow : Window
{
    public MainWindow()
    {
        InitializeComponent();
    }
}
