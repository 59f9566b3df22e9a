using OperatorPanel.Core.Addressing;
using OperatorPanel.Core.Cpu;
using OperatorPanel.Core.Transport;

namespace OperatorPanel.Core.Projects;

/// <summary>Reads an address property: the STL syntax, the shape its list demands, the station's link, then its CPU.</summary>
internal static class AddressReader
{
    /// <summary>Longer text cannot be an address (the longest, "SMB65535", has 8 characters).</summary>
    private const int MaxLength = 16;

    /// <param name="fields">The entry holding the property.</param>
    /// <param name="name">The property, e.g. "address" or "flag".</param>
    /// <param name="cpu">The station's CPU; null when it was unreadable, so only the syntax and shape are checked.</param>
    /// <param name="shape">Null when the address suits the list, else why not ("an input is an I bit...").</param>
    /// <param name="use">Write when the panel will write the address.</param>
    /// <param name="link">
    /// The station's link protocol, which decides the areas it reaches (<see cref="LinkAreas"/>); null when the link
    /// was unreadable (its problem is reported), so only the CPU is checked, as by the link that reaches the most.
    /// </param>
    public static PlcAddress? Read(JsonFields fields, string name, CpuProfile? cpu, Func<PlcAddress, string?> shape, AddressUse use = AddressUse.Read, LinkProtocol? link = null)
    {
        var text = fields.String(name);
        if (text is null)
        {
            return null;
        }

        if (text.Length > MaxLength)
        {
            fields.Problem(name, $"'{JsonPath.Shorten(text)}' is too long to be an address");
            return null;
        }

        if (!PlcAddress.TryParse(text, out var address, out var syntaxError))
        {
            fields.Problem(name, syntaxError.Message);
            return null;
        }

        var refusal = shape(address) ?? (link is { } protocol
            ? LinkAreas.Refusal(address, protocol, cpu, use)
            : cpu is null ? null : AddressRules.Check(address, cpu, use, LinkProtocol.Ppi)?.Message);
        if (refusal is not null)
        {
            fields.Problem(name, refusal);
            return null;
        }

        return address;
    }

    public static string Kind(PlcAddress address) => address.Area switch
    {
        MemoryArea.T => "a timer's current value",
        MemoryArea.C => "a counter's current value",
        _ => address.Width switch
        {
            AccessWidth.Bit => "a bit",
            AccessWidth.Byte => "a byte",
            AccessWidth.Word => "a word",
            AccessWidth.DoubleWord => "a double word",
        },
    };
}
