namespace OperatorPanel.StlGen.Tests.Differential;

/// <summary>Characters the PC sends back to back, starting <paramref name="GapBefore"/> after the previous chunk's last one.</summary>
internal sealed record WireChunk(byte[] Characters, TimeSpan GapBefore)
{
    public static WireChunk Now(byte[] characters) => new(characters, TimeSpan.Zero);
}
