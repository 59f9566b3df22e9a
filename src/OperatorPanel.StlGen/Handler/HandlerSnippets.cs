using OperatorPanel.StlGen.Model;
using static OperatorPanel.StlGen.Handler.HandlerContext;
using static OperatorPanel.StlGen.Handler.HandlerLayout;

namespace OperatorPanel.StlGen.Handler;

/// <summary>Pieces several parts of the handler share.</summary>
internal static class HandlerSnippets
{
    /// <summary>
    /// Protocol area codes 1-5 and the first byte of each area (docs/protocol-v2.md, "Area codes"), tested in this order:
    /// V and M hold most of a panel's values, and each test that matches ends the search with a jump.
    /// </summary>
    private static readonly (int Code, string Pointer, string Name)[] Areas =
        [(4, "&VB0", "V"), (3, "&MB0", "M"), (1, "&IB0", "I"), (2, "&QB0", "Q"), (5, "&SMB0", "SM")];

    /// <summary>Every READ list is forgotten: no list stored, floor back at 256 (docs/protocol-v2.md, "Lists", invalidation).</summary>
    public static NetworkBuilder ClearLists(this NetworkBuilder net, HandlerLayout l) =>
        net.Op("MOVB", "16#FF", l.B(LastFree)).Op("MOVB", "0", l.B(MaxD)).Op("MOVD", "0", l.Dw(LCount1));

    public static StlNetwork Label(int label, string title) =>
        new NetworkBuilder($"Label {label}: {title}").Op("LBL", Dec(label)).Build();

    public static StlNetwork Always(string title, string comment, params (string Mnemonic, string[] Operands)[] ops)
    {
        var net = new NetworkBuilder(title, comment).Op("LD", "SM0.0");
        foreach (var (mnemonic, operands) in ops)
        {
            net.Op(mnemonic, operands);
        }

        return net.Build();
    }

    /// <summary>A one-line condition network: the compare (or bit) and a jump.</summary>
    public static StlNetwork JumpIf(string title, string comment, int label, params (string Mnemonic, string[] Operands)[] condition)
    {
        var net = new NetworkBuilder(title, comment);
        foreach (var (mnemonic, operands) in condition)
        {
            net.Op(mnemonic, operands);
        }

        return net.Op("JMP", Dec(label)).Build();
    }

    /// <summary>
    /// A condition network that ends the subroutine for this scan: CRET (RET's 13 us, docs/sources/s7200-facts.md
    /// section 6) where a JMP to a label at the block's end is charged 46 us.
    /// </summary>
    public static StlNetwork ReturnIf(string title, string comment, params (string Mnemonic, string[] Operands)[] condition)
    {
        var net = new NetworkBuilder(title, comment);
        foreach (var (mnemonic, operands) in condition)
        {
            net.Op(mnemonic, operands);
        }

        return net.Op("CRET").Build();
    }

    public static (string, string[]) Op(string mnemonic, params string[] operands) => (mnemonic, operands);

    /// <summary>
    /// AC3 = pointer to the first byte of the area whose protocol code is in <paramref name="code"/> (checked before);
    /// the code goes on at label <paramref name="found"/>, which ends these networks.
    /// </summary>
    public static IEnumerable<StlNetwork> AreaStart(string code, int found)
    {
        foreach (var (value, pointer, name) in Areas)
        {
            var net = new NetworkBuilder($"Area code {value}: {name}", $"AC3 points at {pointer[1..]}, the first byte of {name}.")
                .Op("LDB=", code, Dec(value)).Op("MOVD", pointer, "AC3");
            yield return (value == Areas[^1].Code ? net : net.Op("JMP", Dec(found))).Build();
        }

        yield return Label(found, "area start found");
    }

    /// <summary>
    /// AC2 = pointer to buffer byte LAST_FREE + 1 - 4N (just below the stored lists), and the 4N descriptor bytes,
    /// already binary after the in-place ATH, copied there from buffer byte <paramref name="source"/>.
    /// </summary>
    public static StlNetwork PlaceDescriptors(HandlerLayout l, int source) =>
        new NetworkBuilder(
                "Descriptors below the stored lists",
                "AC0 = LAST_FREE + 1 - 4N, the first byte of N descriptors of 4 bytes just below the floor.",
                $"AC2 points there; BMB copies AREA, OFFSET, LENGTH of every item from buffer byte {source}.")
            .Op("LD", "SM0.0").Op("BTI", l.B(LastFree), "AC0").Op("INCW", "AC0").Op("BTI", l.B(N), "AC3")
            .Op("SLW", "AC3", "2").Op("-I", "AC3", "AC0").Op("ITD", "AC0", "AC0").Op("MOVD", l.Ptr(0), "AC2")
            .Op("+D", "AC0", "AC2").Op("BMB", l.B(source), "*AC2", "AC3").Build();
}
