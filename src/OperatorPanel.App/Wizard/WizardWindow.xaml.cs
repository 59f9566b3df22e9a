using System.ComponentModel;
using System.Windows;
using OperatorPanel.ViewModels.Wizard;

namespace OperatorPanel.App.Wizard;

/// <summary>
/// The five-step project wizard (also the editor of an existing project). Visual concerns only: it closes itself
/// when the view model has a result, tells the view model when it closed, and hands clipboard text to the symbol paste.
/// </summary>
public partial class WizardWindow : Window
{
    private readonly ProjectWizardViewModel _wizard;

    public WizardWindow(ProjectWizardViewModel wizard)
    {
        ArgumentNullException.ThrowIfNull(wizard);
        _wizard = wizard;
        DataContext = wizard;
        InitializeComponent();
        wizard.PropertyChanged += OnWizardChanged;
        Closed += (_, _) => wizard.Close();
    }

    private void OnWizardChanged(object? sender, PropertyChangedEventArgs e)
    {
        if (e.PropertyName == nameof(ProjectWizardViewModel.IsFinished) && _wizard.IsFinished)
        {
            DialogResult = true;
        }
    }

    private void OnPasteSymbols(object sender, RoutedEventArgs e)
    {
        if (Clipboard.ContainsText())
        {
            _wizard.IoStep.PasteCommand.Execute(Clipboard.GetText());
        }
    }
}
