using OperatorPanel.Core.Addressing;
using OperatorPanel.Core.Transport;

namespace OperatorPanel.ViewModels.Wizard;

/// <summary>An address typed in a wizard row: the STL syntax, the shape its table demands, then the link and the CPU (LinkAreas).</summary>
internal static class WizardAddress
{
    /// <summary>Null when <paramref name="text"/> is a fitting address; otherwise the reason, naming the text.</summary>
    public static string? Check(string text, WizardContext context, AddressUse use, Func<PlcAddress, string?> shape, out PlcAddress address)
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

        if (shape(address) is { } misfit)
        {
            return misfit;
        }

        var refusal = LinkAreas.Refusal(address, context.Link, context.Cpu, use);
        return refusal is not null && context.Link == LinkProtocol.Freeport && LinkAreas.Refusal(address, LinkProtocol.Ppi, context.Cpu, use) is null
            ? $"{refusal} (choose PPI in step 5, Link)"
            : refusal;
    }

    public static bool IsBitOf(PlcAddress address, params MemoryArea[] areas) =>
        address.Width == AccessWidth.Bit && areas.Contains(address.Area);
}
