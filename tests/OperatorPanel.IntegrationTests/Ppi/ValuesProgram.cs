namespace OperatorPanel.IntegrationTests.Ppi;

/// <summary>A program that puts known values where only PPI reads them: a timer, a counter (negative) and an analog output.</summary>
internal static class ValuesProgram
{
    public const string Awl =
        "ORGANIZATION_BLOCK MAIN:OB1\r\nBEGIN\r\nNetwork 1\r\nLD SM0.0\r\nMOVW 250, T37\r\nMOVW -7, C5\r\nMOVW 1234, AQW0\r\nEND_ORGANIZATION_BLOCK\r\n";
}
