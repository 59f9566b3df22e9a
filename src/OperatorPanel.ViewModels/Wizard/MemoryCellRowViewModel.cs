using OperatorPanel.Core.Addressing;
using OperatorPanel.Core.Projects;

namespace OperatorPanel.ViewModels.Wizard;

/// <summary>
/// A memory cell being edited: symbol, address, display format, writable, comment, and as an HMI has them a unit, a
/// linear scale ("0..1000 -> 0..100") and the range the operator may write ("1..8"), typed as text and checked by the
/// step (TagScale, TagRange, TagRules). When a new address does not fit the chosen format (VW100 shown as Bool), the
/// format falls back to the address's default, as the project file does.
/// </summary>
public sealed class MemoryCellRowViewModel : WizardRowViewModel
{
    private string _symbol;
    private string _address;
    private DisplayFormat _format;
    private bool _writable;
    private string _description;
    private string _unit = string.Empty;
    private string _scale = string.Empty;
    private string _range = string.Empty;

    public MemoryCellRowViewModel(string symbol = "", string address = "", DisplayFormat format = DisplayFormat.Unsigned, bool writable = false, string description = "")
    {
        (_symbol, _address, _format, _writable, _description) = (symbol, address, format, writable, description);
    }

    internal MemoryCellRowViewModel(ProjectTag tag)
        : this(tag.Symbol, tag.Address.ToString(), tag.Format, tag.Writable, tag.Description)
    {
        (_unit, _scale, _range) = (tag.Unit ?? string.Empty, tag.Scale?.ToString() ?? string.Empty, tag.Range?.ToString() ?? string.Empty);
    }

    /// <summary>Every format; the ones that fit the address are <see cref="FittingFormats"/>.</summary>
    public static IReadOnlyList<DisplayFormat> Formats { get; } = Enum.GetValues<DisplayFormat>();

    public IReadOnlyList<DisplayFormat> FittingFormats =>
        PlcAddress.TryParse(Address.Trim(), out var a, out _) ? [.. Formats.Where(f => f.Fits(a.Width))] : Formats;

    public string Symbol { get => _symbol; set => Edit(ref _symbol, value ?? string.Empty); }

    public string Address
    {
        get => _address;
        set
        {
            Edit(ref _address, value ?? string.Empty);
            OnPropertyChanged(nameof(FittingFormats));
            if (PlcAddress.TryParse(_address.Trim(), out var address, out _) && !Format.Fits(address.Width))
            {
                Format = DisplayFormats.DefaultFor(address.Width);
            }
        }
    }

    public DisplayFormat Format { get => _format; set => Edit(ref _format, value); }

    /// <summary>True when the operator may change the cell from the memory window.</summary>
    public bool Writable { get => _writable; set => Edit(ref _writable, value); }

    public string Description { get => _description; set => Edit(ref _description, value ?? string.Empty); }

    /// <summary>Shown after the value ("%", "ml"); empty for none.</summary>
    public string Unit { get => _unit; set => Edit(ref _unit, value ?? string.Empty); }

    /// <summary>"0..1000 -> 0..100": raw PLC number to the value shown (numbers only); empty for none.</summary>
    public string Scale { get => _scale; set => Edit(ref _scale, value ?? string.Empty); }

    /// <summary>"1..8", "0..", "..100": what the operator may write, in the shown units; empty for no limit but the width's.</summary>
    public string Range { get => _range; set => Edit(ref _range, value ?? string.Empty); }
}
