using System.Windows;
using OperatorPanel.ViewModels.Generate;

namespace OperatorPanel.App.Generate;

/// <summary>
/// Generate PLC code over <see cref="GenerateCodeViewModel"/>, non-modal so the panel's windows stay live beside it.
/// Visual concerns only: the main window opens it while the shell's GenerateCode is set and tells the shell when it closes.
/// </summary>
public partial class GenerateCodeWindow : Window
{
    public GenerateCodeWindow(GenerateCodeViewModel generate)
    {
        ArgumentNullException.ThrowIfNull(generate);
        DataContext = generate;
        InitializeComponent();
    }

    private void OnClose(object sender, RoutedEventArgs e) => Close();
}
