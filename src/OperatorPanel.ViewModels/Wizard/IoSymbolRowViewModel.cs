using OperatorPanel.Core.Projects;

namespace OperatorPanel.ViewModels.Wizard;

/// <summary>An input or output symbol being edited: symbol, address (I bit or Q bit) and comment, as typed.</summary>
public sealed class IoSymbolRowViewModel : WizardRowViewModel
{
    private string _symbol;
    private string _address;
    private string _description;

    public IoSymbolRowViewModel(string symbol = "", string address = "", string description = "")
    {
        _symbol = symbol;
        _address = address;
        _description = description;
    }

    internal IoSymbolRowViewModel(IoSymbol symbol)
        : this(symbol.Symbol, symbol.Address.ToString(), symbol.Description)
    {
    }

    public string Symbol { get => _symbol; set => Edit(ref _symbol, value ?? string.Empty); }

    public string Address { get => _address; set => Edit(ref _address, value ?? string.Empty); }

    public string Description { get => _description; set => Edit(ref _description, value ?? string.Empty); }
}
