using System.Globalization;
using OperatorPanel.Core.Protocol;
using OperatorPanel.StlGen.Model;
using static OperatorPanel.StlGen.Handler.HandlerContext;
using static OperatorPanel.StlGen.Handler.HandlerLayout;
using static OperatorPanel.StlGen.Handler.HandlerSnippets;

namespace OperatorPanel.StlGen.Handler;

/// <summary>
/// 01 IDENTIFY: the 22-byte payload of docs/protocol-v2.md section 2, written as 44 characters from buffer byte 14: v1's
/// 15 bytes (protocol version 2), then PORT, V_FIRST, V_BYTES, FEATURES and COPY_BYTES, all fixed at generation.
/// </summary>
internal static class IdentifyPart
{
    /// <summary>Buffer byte of SMB6's 2 characters, after the 7 fixed bytes.</summary>
    private const int CpuId = ReplyPart.PayloadStart + 14;

    /// <summary>STATUS_FLAGS, then the 3 scan-time words, then the v2 bytes.</summary>
    private const int Flags = CpuId + 2, ScanTimes = Flags + 2, Memory = ScanTimes + 12, End = Memory + 14;

    public static IEnumerable<StlNetwork> Networks(HandlerContext c)
    {
        var l = c.Layout;
        var fixedBytes = new[]
        {
            HandlerIdentity.ProtocolVersion, HandlerIdentity.HandlerRevision, HandlerIdentity.CpuModelCode(c.Options.Cpu.Model),
            HandlerIdentity.CpuRevisionCode(c.Options.Cpu.Revision), (byte)c.Options.WriteMask, HandlerIdentity.MaxReadData,
            (byte)c.Options.ReplyDelayMs,
        };
        int[] memoryBytes = [c.Port, l.BufferStart >> 8, l.BufferStart & 0xFF, c.HandlerVBytes >> 8, c.HandlerVBytes & 0xFF, c.Features, c.CopyBytes];
        var chars = HexChars(fixedBytes.Select(b => (int)b));
        var memory = HexChars(memoryBytes);
        yield return Label(HandlerLabels.Identify, "01 IDENTIFY");
        yield return JumpIf(
            "IDENTIFY: body exactly 3 bytes", $"Error 04 unless count = {RequestChars(0)}.", HandlerLabels.Error(ProtocolError.BadLength),
            Op("LDB<>", l.B(0), RequestChars(0)));
        yield return new NetworkBuilder(
                "IDENTIFY: fixed part of the reply",
                $"Characters '{chars}': protocol {HandlerIdentity.ProtocolVersion}, revision, CPU model and revision, write mask, {HandlerIdentity.MaxReadData}, reply delay.",
                "Then SMB6 (CPU identification) as 2 characters and STATUS_FLAGS '00' (bit 0 set below).")
            .Op("LD", "SM0.0").Ops(Text(l, ReplyPart.PayloadStart, chars))
            .Op("HTA", "SMB6", l.B(CpuId), "2").Op("MOVW", "16#3030", l.W(Flags)).Build();
        yield return new NetworkBuilder("IDENTIFY: mode switch at RUN", "STATUS_FLAGS bit 0 = SM0.7: character '1'.")
            .Op("LD", "SM0.7").Op("MOVB", "16#31", l.B(Flags + 1)).Build();
        yield return new NetworkBuilder(
                "IDENTIFY: scan times and the handler's memory",
                "SMW22 last, SMW24 minimum, SMW26 maximum scan time: 12 characters. Then",
                $"'{memory}': port {c.Port}, V_FIRST {l.BufferStart}, V_BYTES {c.HandlerVBytes}, FEATURES {c.Features}, COPY_BYTES {c.CopyBytes}.",
                $"The reply payload ends before byte {End}.")
            .Op("LD", "SM0.0").Op("HTA", "SMB22", l.B(ScanTimes), "12").Ops(Text(l, Memory, memory))
            .Op("MOVD", l.Ptr(End), "AC1").Op("MOVB", "0", l.B(List)).Op("JMP", Dec(HandlerLabels.Finish)).Build();
    }

    private static string HexChars(IEnumerable<int> bytes) => string.Concat(bytes.Select(b => b.ToString("X2", CultureInfo.InvariantCulture)));

    /// <summary>MOVD per 4 characters and MOVW for the last 2: the constants that put <paramref name="text"/> at buffer byte <paramref name="offset"/>.</summary>
    private static IEnumerable<(string, string[])> Text(HandlerLayout l, int offset, string text)
    {
        for (var i = 0; i < text.Length; i += 4)
        {
            yield return text.Length - i >= 4
                ? Op("MOVD", Chars(text.Substring(i, 4)), l.Dw(offset + i))
                : Op("MOVW", Chars(text[i..]), l.W(offset + i));
        }
    }

    /// <summary>"0101" as the constant 16#30313031 that puts those characters in memory, high byte first.</summary>
    private static string Chars(string text) =>
        "16#" + string.Concat(text.Select(ch => ((int)ch).ToString("X2", CultureInfo.InvariantCulture)));
}
