using System.Text;
using OperatorPanel.Core.Transport;

namespace OperatorPanel.TestKit;

/// <summary>The bus side of an in-memory pair as a test plays the PLC: frames read whole, as the text on the wire.</summary>
public static class FreeportWire
{
    /// <summary>A frame as its ASCII text ("&lt;0201...&gt;").</summary>
    public static string Text(byte[] frame) => Encoding.ASCII.GetString(frame);

    /// <summary>Reads from <paramref name="end"/> until a frame's closing '&gt;' (each read waits at most 5 s).</summary>
    public static async Task<string> ReadFrameAsync(InMemoryTransport end)
    {
        ArgumentNullException.ThrowIfNull(end);
        var text = string.Empty;
        var buffer = new byte[256];
        while (!text.EndsWith('>'))
        {
            var count = await end.ReadAsync(buffer, TimeSpan.FromSeconds(5), default);
            text += Encoding.ASCII.GetString(buffer, 0, count);
        }

        return text;
    }
}
