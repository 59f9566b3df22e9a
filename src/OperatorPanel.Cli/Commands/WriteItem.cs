using System.Diagnostics.CodeAnalysis;
using OperatorPanel.Cli.Link;
using OperatorPanel.Core.Addressing;
using OperatorPanel.Core.Projects;
using OperatorPanel.Core.Values;
using OperatorPanel.Core.Writes;

namespace OperatorPanel.Cli.Commands;

/// <summary>One <c>ADDR=VALUE</c> of <c>opanel write</c>, checked: the address, the format its notation implies, the request.</summary>
internal sealed record WriteItem(PlcAddress Address, DisplayFormat Format, WriteRequest Request)
{
    public static bool TryParse(string text, LinkTarget target, [NotNullWhen(true)] out WriteItem? item, [NotNullWhen(false)] out string? error)
    {
        item = null;
        var equals = text.IndexOf('=', StringComparison.Ordinal);
        if (equals < 0)
        {
            error = $"'{text}': write ADDR=VALUE, e.g. VW200=1234";
            return false;
        }

        if (!AddressArguments.TryParse(text[..equals], target.Cpu, AddressUse.Write, out var address, out error))
        {
            return false;
        }

        var valueText = text[(equals + 1)..];
        var format = ValueFormatInference.Infer(valueText, address.Width);
        if (!ValueParser.TryParse(valueText, address, format, out var bytes, out var valueError))
        {
            error = valueError.Message;
            return false;
        }

        var request = address.Width == AccessWidth.Bit
            ? WriteRequest.Bit(target.Station, address, bytes[0] != 0)
            : WriteRequest.Bytes(target.Station, address, bytes);
        item = new WriteItem(address, format, request);
        return true;
    }

    /// <summary>Bytes in this item's format; "?" when unknown.</summary>
    public string Show(ReadOnlySpan<byte> raw) => raw.IsEmpty ? "?" : ValueFormatter.Format(raw, Address.Width, Format);
}
