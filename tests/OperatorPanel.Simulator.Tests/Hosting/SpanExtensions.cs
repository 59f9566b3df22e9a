namespace OperatorPanel.Simulator.Tests.Hosting;

internal static class SpanExtensions
{
    public static void SetBytes(this Span<byte> target, byte[] values) => values.CopyTo(target);
}
