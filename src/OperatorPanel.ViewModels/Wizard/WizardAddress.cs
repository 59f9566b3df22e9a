using OperatorPanel.Core.Addressing;
using OperatorPanel.Core.Cpu;

namespace OperatorPanel.ViewModels.Wizard;

/// <summary>An address typed in a wizard row: the STL syntax, the shape its table demands, then the CPU (AddressRules).</summary>
internal static class WizardAddress
{
    /// <summary>Null when <paramref name="text"/> is a fitting address; otherwise the reason, naming the text.</summary>
    public static string? Check(string text, CpuProfile cpu, AddressUse use, Func<PlcAddress, string?> shape, out PlcAddress address)
    {
        address = default;
        if (string.IsNullOrWhiteSpace(text))
        {
            return "no address given";
        }

        if (!PlcAddress.TryParse(text.Trim(), out address, out var syntax))
        {
            return syntax.Message;
        }

        return shape(address) ?? AddressRules.Check(address, cpu, use)?.Message;
    }

    public static bool IsBitOf(PlcAddress address, params MemoryArea[] areas) =>
        address.Width == AccessWidth.Bit && areas.Contains(address.Area);
}
