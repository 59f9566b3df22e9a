using System.Windows;
using OperatorPanel.ViewModels.Help;

namespace OperatorPanel.App.Help;

/// <summary>Help > About; all content is AboutViewModel's. Close (or Esc) closes it: IsCancel does that on its own.</summary>
public partial class AboutWindow : Window
{
    public AboutWindow(AboutViewModel about)
    {
        DataContext = about;
        InitializeComponent();
    }
}
