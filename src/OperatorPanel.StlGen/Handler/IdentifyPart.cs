using System.Globalization;
using OperatorPanel.Core.Protocol;
using OperatorPanel.StlGen.Model;
using static OperatorPanel.StlGen.Handler.HandlerContext;
using static OperatorPanel.StlGen.Handler.HandlerLayout;
using static OperatorPanel.StlGen.Handler.HandlerSnippets;

namespace OperatorPanel.StlGen.Handler;

/// <summary>01 IDENTIFY: the 15-byte payload of docs/protocol.md section 2, written as 30 characters from buffer byte 10.</summary>
internal static class IdentifyPart
{
    public static IEnumerable<StlNetwork> Networks(HandlerContext c)
    {
        var l = c.Layout;
        var fixedBytes = new[]
        {
            HandlerIdentity.ProtocolVersion, HandlerIdentity.HandlerRevision, HandlerIdentity.CpuModelCode(c.Options.Cpu.Model),
            HandlerIdentity.CpuRevisionCode(c.Options.Cpu.Revision), (byte)c.Options.WriteMask, HandlerIdentity.MaxReadData,
            (byte)c.Options.ReplyDelayMs,
        };
        var chars = string.Concat(fixedBytes.Select(b => b.ToString("X2", CultureInfo.InvariantCulture)));
        yield return Label(HandlerLabels.Identify, "01 IDENTIFY");
        yield return JumpIf("IDENTIFY: body exactly 4 bytes", "Error 04 unless count = 10.", HandlerLabels.Error(ProtocolError.BadLength), Op("LDB<>", l.B(0), "10"));
        yield return new NetworkBuilder(
                "IDENTIFY: fixed part of the reply",
                $"Characters '{chars}': protocol 1, revision 1, CPU model and revision, write mask, 119, reply delay.",
                "Then SMB6 (CPU identification) as 2 characters and STATUS_FLAGS '00' (bit 0 set below).")
            .Op("LD", "SM0.0").Op("MOVD", Chars(chars[..4]), l.Dw(10)).Op("MOVD", Chars(chars[4..8]), l.Dw(14))
            .Op("MOVD", Chars(chars[8..12]), l.Dw(18)).Op("MOVW", Chars(chars[12..]), l.W(22))
            .Op("HTA", "SMB6", l.B(24), "2").Op("MOVW", "16#3030", l.W(26)).Build();
        yield return new NetworkBuilder("IDENTIFY: mode switch at RUN", "STATUS_FLAGS bit 0 = SM0.7: character '1'.")
            .Op("LD", "SM0.7").Op("MOVB", "16#31", l.B(27)).Build();
        yield return Always(
            "IDENTIFY: scan times",
            "SMW22 last, SMW24 minimum, SMW26 maximum scan time: 12 characters. The reply payload ends before byte 40.",
            Op("HTA", "SMB22", l.B(28), "12"), Op("MOVD", l.Ptr(40), "AC1"), Op("MOVB", "0", l.B(List)), Op("JMP", Dec(HandlerLabels.Finish)));
    }

    /// <summary>"0101" as the constant 16#30313031 that puts those characters in memory, high byte first.</summary>
    private static string Chars(string text) =>
        "16#" + string.Concat(text.Select(ch => ((int)ch).ToString("X2", CultureInfo.InvariantCulture)));
}
